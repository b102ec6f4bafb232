#include "mechanics/core/axis_ode.hpp"

#include <algorithm>
#include <cmath>


namespace cnc::mech {

namespace {

constexpr double kShaftStickBandRad_s = 0.01;  // the shaft may stick below 0.1 rpm

}  // namespace

AxisOde::AxisOde(const AxisParams& params) : m_p(params) {
    validate(m_p.motor);
    validate(m_p.load);
}

namespace {

// The voltage each winding's bridge wants at state x (drv8825_current.hpp), and the back-EMF it contains.
struct WantedVoltages {
    std::array<double, 2> wanted_v;
    std::array<double, 2> emf_v;
};

WantedVoltages wanted_voltages(const AxisParams& p, const AxisSetpoints& sp, const AxisState& x, RotorAngle angle) {
    const HybridStepperParams& m = p.motor;
    const WindingCurrents emf = back_emf_v(m, angle, x[kOmega]);
    return {{wanted_voltage_v(sp.current.a_a, x[kIa], emf.a_a, m.resistance_ohm, m.inductance_h, p.driver),
             wanted_voltage_v(sp.current.b_a, x[kIb], emf.b_a, m.resistance_ohm, m.inductance_h, p.driver)},
            {emf.a_a, emf.b_a}};
}

}  // namespace

void AxisOde::derivative(const AxisState& x, AxisState& dxdt, const AxisModes& modes, RotorAngle angle) const {
    const HybridStepperParams& m = m_p.motor;
    const double theta = x[kTheta];
    const double omega = x[kOmega];
    const WantedVoltages v = wanted_voltages(m_p, m_sp, x, angle);
    for (int k = 0; k < 2; ++k) {
        const double bridge_v = bridge_voltage_v(modes.bridges[k], v.wanted_v[k], m_p.driver);
        dxdt[k] = (bridge_v - m.resistance_ohm * x[k] - v.emf_v[k]) / m.inductance_h;
    }

    const CouplingForces f = coupling_forces(m_p.load, theta, omega, x[kX], x[kV]);
    const double other = electromagnetic_torque_nm(m, angle, {x[kIa], x[kIb]}) + detent_torque_nm(m, angle) +
                         f.on_rotor_nm - m.viscous_nm_per_rad_s * omega + m_sp.external_torque_nm;
    const double torque = other + coulomb_friction(modes.shaft, m.coulomb_nm, omega, other, m.rotor_inertia_kgm2);
    dxdt[kTheta] = omega;
    dxdt[kOmega] = torque / m.rotor_inertia_kgm2;
    if (m_p.load.kind == DriveKind::Free) {
        dxdt[kX] = 0.0;
        dxdt[kV] = 0.0;
        return;
    }
    dxdt[kX] = x[kV];
    dxdt[kV] = (f.on_carriage_n + rail_friction_n(m_p.load, x[kV], f.on_carriage_n, modes.rail)) / m_p.load.carriage_mass_kg;
}

AxisModes AxisOde::modes(const AxisState& x, RotorAngle angle) const {
    const WantedVoltages v = wanted_voltages(m_p, m_sp, x, angle);
    return {{bridge_mode(v.wanted_v[0], m_p.driver), bridge_mode(v.wanted_v[1], m_p.driver)},
            friction_mode(x[kOmega], kShaftStickBandRad_s),
            friction_mode(x[kV], kRailStickBandM_s)};
}

AxisOde::ModeMargins AxisOde::mode_margins(const AxisState& x, const AxisModes& modes, RotorAngle angle) const {
    const WantedVoltages v = wanted_voltages(m_p, m_sp, x, angle);
    const double vmot = m_p.driver.supply_v;
    return {mode_margin_v(modes.bridges[0], v.wanted_v[0], m_p.driver) / vmot,
            mode_margin_v(modes.bridges[1], v.wanted_v[1], m_p.driver) / vmot,
            friction_margin(modes.shaft, x[kOmega], kShaftStickBandRad_s),
            friction_margin(modes.rail, x[kV], kRailStickBandM_s)};
}

double AxisOde::regulation_rate_per_s() const {
    return mech::regulation_rate_per_s(m_p.motor.resistance_ohm, m_p.motor.inductance_h, m_p.driver);
}

double AxisOde::mechanical_energy_j(const AxisState& x) const {
    const double kinetic = 0.5 * m_p.motor.rotor_inertia_kgm2 * x[kOmega] * x[kOmega] +
                           (m_p.load.kind == DriveKind::Free ? 0.0 : 0.5 * m_p.load.carriage_mass_kg * x[kV] * x[kV]);
    return kinetic + coupling_energy_j(m_p.load, x[kTheta], x[kX]) + detent_energy_j(m_p.motor, x[kTheta]);
}

}  // namespace cnc::mech
