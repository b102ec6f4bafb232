#include "mechanics/core/axis_ode.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mechanics/core/friction.hpp"

namespace cnc::mech {

namespace {

constexpr double kShaftStickBandRad_s = 0.01;  // the shaft may stick below 0.1 rpm

}  // namespace

AxisOde::AxisOde(const AxisParams& params) : m_p(params) {
    validate(m_p.motor);
    validate(m_p.load);
}

void AxisOde::operator()(const AxisState& x, AxisState& dxdt, double) const {
    const HybridStepperParams& m = m_p.motor;
    const double theta = x[kTheta];
    const double omega = x[kOmega];
    const RotorAngle angle = rotor_angle(m, theta);
    const WindingCurrents emf = back_emf_v(m, angle, omega);
    const double va = bridge_voltage_v(m_sp.current.a_a, x[kIa], emf.a_a, m.resistance_ohm, m.inductance_h, m_p.driver);
    const double vb = bridge_voltage_v(m_sp.current.b_a, x[kIb], emf.b_a, m.resistance_ohm, m.inductance_h, m_p.driver);
    dxdt[kIa] = (va - m.resistance_ohm * x[kIa] - emf.a_a) / m.inductance_h;
    dxdt[kIb] = (vb - m.resistance_ohm * x[kIb] - emf.b_a) / m.inductance_h;

    const CouplingForces f = coupling_forces(m_p.load, theta, omega, x[kX], x[kV]);
    const double other = electromagnetic_torque_nm(m, angle, {x[kIa], x[kIb]}) + detent_torque_nm(m, angle) +
                         f.on_rotor_nm - m.viscous_nm_per_rad_s * omega + m_sp.external_torque_nm;
    const double torque =
        other + coulomb_friction(m.coulomb_nm, omega, other, m.rotor_inertia_kgm2, kShaftStickBandRad_s);
    dxdt[kTheta] = omega;
    dxdt[kOmega] = torque / m.rotor_inertia_kgm2;
    if (m_p.load.kind == DriveKind::Free) {
        dxdt[kX] = 0.0;
        dxdt[kV] = 0.0;
        return;
    }
    dxdt[kX] = x[kV];
    dxdt[kV] = (f.on_carriage_n + rail_friction_n(m_p.load, x[kV], f.on_carriage_n)) / m_p.load.carriage_mass_kg;
}

AxisOde::Bridges AxisOde::bridges(const AxisState& x, const AxisState& dxdt) const {
    const HybridStepperParams& m = m_p.motor;
    const WindingCurrents emf = back_emf_v(m, rotor_angle(m, x[kTheta]), x[kOmega]);
    const std::array<double, 2> ref{m_sp.current.a_a, m_sp.current.b_a};
    const std::array<double, 2> e{emf.a_a, emf.b_a};
    Bridges b{{false, false}, std::numeric_limits<double>::infinity()};
    for (int k = 0; k < 2; ++k) {
        b.regulate[k] = bridge_regulates(ref[k], x[k], e[k], m.resistance_ohm, m.inductance_h, m_p.driver);
        if (b.regulate[k]) continue;
        b.time_to_regulation_s = std::min(b.time_to_regulation_s,
                                          time_to_regulation_s(ref[k], x[k], e[k], m.resistance_ohm,
                                                               m.inductance_h, m_p.driver, dxdt[k]));
    }
    return b;
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
