#include "mechanics/core/axis_ode.hpp"

#include <algorithm>
#include <cmath>

namespace cnc::mech {

namespace {

constexpr double kShaftStickBandRad_s = 0.01;  // the shaft may stick below 0.1 rpm

}  // namespace

struct AxisOde::WantedVoltages {
    std::array<double, 2> wanted_v;
    std::array<double, 2> emf_v;
};

AxisOde::AxisOde(const AxisParams& params)
    : m_p(params),
      m_coupling(params.load),
      m_km_nm_per_a(params.motor.torque_constant_nm_per_a()),
      m_l_per_tau_ohm(params.motor.inductance_h / params.driver.chop_tau_s),
      m_inv_inductance_per_h(1.0 / params.motor.inductance_h),
      m_inv_inertia_per_kgm2(1.0 / params.motor.rotor_inertia_kgm2),
      m_inv_mass_per_kg(params.load.kind == DriveKind::Free ? 0.0 : 1.0 / params.load.carriage_mass_kg),
      m_rate_per_s(mech::regulation_rate_per_s(params.motor.resistance_ohm, params.motor.inductance_h, params.driver)) {
    validate(m_p.motor);
    validate(m_p.load);
}

AxisOde::WantedVoltages AxisOde::wanted_voltages(const AxisState& x, RotorAngle angle) const {
    const double r = m_p.motor.resistance_ohm;
    const WindingCurrents emf = back_emf_v(m_km_nm_per_a, angle, x[kOmega]);
    return {{wanted_voltage_v(m_sp.current.a_a, x[kIa], emf.a_a, r, m_l_per_tau_ohm),
             wanted_voltage_v(m_sp.current.b_a, x[kIb], emf.b_a, r, m_l_per_tau_ohm)},
            {emf.a_a, emf.b_a}};
}

void AxisOde::derivative(const AxisState& x, AxisState& dxdt, const AxisModes& modes, RotorAngle angle) const {
    const HybridStepperParams& m = m_p.motor;
    const double theta = x[kTheta];
    const double omega = x[kOmega];
    const WantedVoltages v = wanted_voltages(x, angle);
    for (int k = 0; k < 2; ++k) {
        const double bridge_v = bridge_voltage_v(modes.bridges[k], v.wanted_v[k], m_p.driver);
        dxdt[k] = (bridge_v - m.resistance_ohm * x[k] - v.emf_v[k]) * m_inv_inductance_per_h;
    }

    const CouplingForces f = m_coupling.forces(theta, omega, x[kX], x[kV]);
    const double other = electromagnetic_torque_nm(m_km_nm_per_a, angle, {x[kIa], x[kIb]}) +
                         detent_torque_nm(m, angle) + f.on_rotor_nm - m.viscous_nm_per_rad_s * omega +
                         m_sp.external_torque_nm;
    const double torque = other + coulomb_friction(modes.shaft, m.coulomb_nm, omega, other, m.rotor_inertia_kgm2);
    dxdt[kTheta] = omega;
    dxdt[kOmega] = torque * m_inv_inertia_per_kgm2;
    if (m_p.load.kind == DriveKind::Free) {
        dxdt[kX] = 0.0;
        dxdt[kV] = 0.0;
        return;
    }
    dxdt[kX] = x[kV];
    dxdt[kV] = (f.on_carriage_n + rail_friction_n(m_p.load, x[kV], f.on_carriage_n, modes.rail)) * m_inv_mass_per_kg;
}

AxisModes AxisOde::modes(const AxisState& x, RotorAngle angle) const {
    const WantedVoltages v = wanted_voltages(x, angle);
    return {{bridge_mode(v.wanted_v[0], m_p.driver), bridge_mode(v.wanted_v[1], m_p.driver)},
            friction_mode(x[kOmega], kShaftStickBandRad_s),
            friction_mode(x[kV], kRailStickBandM_s)};
}

AxisOde::ModeMargins AxisOde::mode_margins(const AxisState& x, const AxisModes& modes, RotorAngle angle) const {
    const WantedVoltages v = wanted_voltages(x, angle);
    const double vmot = m_p.driver.supply_v;
    return {mode_margin_v(modes.bridges[0], v.wanted_v[0], m_p.driver) / vmot,
            mode_margin_v(modes.bridges[1], v.wanted_v[1], m_p.driver) / vmot,
            friction_margin(modes.shaft, x[kOmega], kShaftStickBandRad_s),
            friction_margin(modes.rail, x[kV], kRailStickBandM_s)};
}

double AxisOde::mechanical_energy_j(const AxisState& x) const {
    const double kinetic = 0.5 * m_p.motor.rotor_inertia_kgm2 * x[kOmega] * x[kOmega] +
                           (m_p.load.kind == DriveKind::Free ? 0.0 : 0.5 * m_p.load.carriage_mass_kg * x[kV] * x[kV]);
    return kinetic + m_coupling.energy_j(x[kTheta], x[kX]) + detent_energy_j(m_p.motor, x[kTheta]);
}

}  // namespace cnc::mech
