#include "mechanics/core/drv8825_current.hpp"

#include <algorithm>
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
    const double wanted = resistance_ohm * i_ref_a + emf_v + inductance_h * (i_ref_a - i_a) / drv.chop_tau_s;
    return std::clamp(wanted, -drv.supply_v, drv.supply_v);
}

}  // namespace cnc::mech
