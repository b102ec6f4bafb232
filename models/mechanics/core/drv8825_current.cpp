#include "mechanics/core/drv8825_current.hpp"

#include <cmath>
#include <string>

#include "common/bad_input.hpp"
#include "mechanics/core/drv8825_modes.hpp"

namespace cnc::mech {

double current_limit_from_vref_a(double vref_v, double r_sense_ohm) {
    if (!(r_sense_ohm > 0.0))
        throw BadInput("", "DRV8825 R_SENSE must be > 0 ohm (got " + std::to_string(r_sense_ohm) + ")");
    return vref_v / (5.0 * r_sense_ohm);
}

WindingSetpoints winding_setpoints(std::int64_t units, const DriverElectrics& drv, bool enabled) {
    if (!enabled) return {};
    const PhaseCurrents pct = phase_currents(units);
    return {pct.a_pct / 100.0 * drv.current_limit_a, pct.b_pct / 100.0 * drv.current_limit_a};
}

double bridge_voltage_v(double i_ref_a, double i_a, double emf_v, double resistance_ohm, double inductance_h,
                        const DriverElectrics& drv) {
    const double wanted = wanted_voltage_v(i_ref_a, i_a, emf_v, resistance_ohm, inductance_h / drv.chop_tau_s);
    return bridge_voltage_v(bridge_mode(wanted, drv), wanted, drv);
}

double regulation_rate_per_s(double resistance_ohm, double inductance_h, const DriverElectrics& drv) {
    return 1.0 / drv.chop_tau_s + resistance_ohm / inductance_h;
}

}  // namespace cnc::mech
