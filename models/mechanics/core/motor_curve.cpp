#include "mechanics/core/motor_curve.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <boost/numeric/odeint.hpp>

#include "common/math_constants.hpp"
#include "mechanics/core/drv8825_modes.hpp"
#include "mechanics/core/dynamic_axis.hpp"

namespace cnc::mech {

namespace {

namespace odeint = boost::numeric::odeint;
using Currents = std::array<double, 3>;  // i_a, i_b, integral of the torque

// Settling time before the torque is averaged: 8 winding time constants, and at least one period.
double settle_s(const HybridStepperParams& m, double period_s) {
    return std::max(8.0 * m.inductance_h / m.resistance_ohm, period_s);
}

}  // namespace

double synchronous_torque_nm(const AxisParams& p, int microsteps, double full_steps_per_s, double load_angle_rad) {
    const HybridStepperParams& m = p.motor;
    const double omega = full_steps_per_s * m.full_step_rad();
    const double microstep_s = 1.0 / (full_steps_per_s * microsteps);
    const int units_per_microstep = kIndexerUnitsPerFullStep / microsteps;
    const double period_s = 4.0 / full_steps_per_s;  // one electrical period = 4 full steps
    const double t_settle = settle_s(m, period_s);
    // The command advances one microstep at each k * microstep_s; the rotor trails it by the load angle.
    auto system = [&](const Currents& x, Currents& d, double t) {
        const auto k = static_cast<std::int64_t>(std::floor(t / microstep_s));
        const WindingSetpoints sp = winding_setpoints(k * units_per_microstep, p.driver, true);
        const double theta = omega * t - load_angle_rad / m.rotor_teeth;
        const RotorAngle angle = rotor_angle(m, theta);
        const WindingCurrents emf = back_emf_v(m.torque_constant_nm_per_a(), angle, omega);
        const double va = bridge_voltage_v(sp.a_a, x[0], emf.a_a, m.resistance_ohm, m.inductance_h, p.driver);
        const double vb = bridge_voltage_v(sp.b_a, x[1], emf.b_a, m.resistance_ohm, m.inductance_h, p.driver);
        d[0] = (va - m.resistance_ohm * x[0] - emf.a_a) / m.inductance_h;
        d[1] = (vb - m.resistance_ohm * x[1] - emf.b_a) / m.inductance_h;
        d[2] = electromagnetic_torque_nm(m.torque_constant_nm_per_a(), angle, {x[0], x[1]});
    };
    const WindingSetpoints start = winding_setpoints(0, p.driver, true);
    Currents x{start.a_a, start.b_a, 0.0};
    auto stepper = odeint::make_controlled(1e-9, 1e-7, odeint::runge_kutta_dopri5<Currents>());
    // Integrate microstep by microstep so that no step straddles a set-point change.
    const auto settle_steps = static_cast<std::int64_t>(std::ceil(t_settle / microstep_s));
    const auto measure_steps = static_cast<std::int64_t>(4 * microsteps);
    double torque_at_settle = 0.0;
    const double dt0 = std::min(microstep_s, 1e-5);
    for (std::int64_t k = 0; k < settle_steps + measure_steps; ++k) {
        if (k == settle_steps) torque_at_settle = x[2];
        odeint::integrate_adaptive(stepper, system, x, k * microstep_s, (k + 1) * microstep_s,
                                   std::min(dt0, microstep_s));
    }
    return (x[2] - torque_at_settle) / period_s;
}

double pull_out_torque_nm(const AxisParams& p, int microsteps, double full_steps_per_s) {
    // Coarse scan of the load angle, then a golden-section search around the best.
    double best_angle = 0.0;
    double best = -1e9;
    constexpr int kCoarse = 12;
    for (int i = 0; i <= kCoarse; ++i) {
        const double a = kPi * i / kCoarse;
        const double t = synchronous_torque_nm(p, microsteps, full_steps_per_s, a);
        if (t > best) {
            best = t;
            best_angle = a;
        }
    }
    double lo = best_angle - kPi / kCoarse;
    double hi = best_angle + kPi / kCoarse;
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double a = hi - g * (hi - lo);
    double b = lo + g * (hi - lo);
    double ta = synchronous_torque_nm(p, microsteps, full_steps_per_s, a);
    double tb = synchronous_torque_nm(p, microsteps, full_steps_per_s, b);
    for (int i = 0; i < 8; ++i) {
        if (ta > tb) {
            hi = b;
            b = a;
            tb = ta;
            a = hi - g * (hi - lo);
            ta = synchronous_torque_nm(p, microsteps, full_steps_per_s, a);
        } else {
            lo = a;
            a = b;
            ta = tb;
            b = lo + g * (hi - lo);
            tb = synchronous_torque_nm(p, microsteps, full_steps_per_s, b);
        }
    }
    return std::max({best, ta, tb});
}

double required_torque_nm(const AxisParams& p, double full_steps_per_s) {
    const double omega = full_steps_per_s * p.motor.full_step_rad();
    const double motor = p.motor.viscous_nm_per_rad_s * omega + (omega > 0.0 ? p.motor.coulomb_nm : 0.0);
    if (p.load.kind == DriveKind::Free) return motor;
    const double r = travel_m_per_rad(p.load);
    const double force = -rail_friction_n(p.load, omega * r, 0.0);
    const double efficiency = p.load.kind == DriveKind::Leadscrew ? p.load.screw_efficiency : 1.0;
    return motor + force * r / efficiency;
}

double acceleration_torque_nm(const AxisParams& p, double accel_mm_s2) {
    const double r = travel_m_per_rad(p.load);
    const double alpha = accel_mm_s2 * 1e-3 / r;
    double inertia = p.motor.rotor_inertia_kgm2;
    if (p.load.kind != DriveKind::Free) {
        const double efficiency = p.load.kind == DriveKind::Leadscrew ? p.load.screw_efficiency : 1.0;
        inertia += p.load.carriage_mass_kg * r * r / efficiency;
    }
    return inertia * alpha;
}

bool starts_without_loss(const AxisParams& p, int microsteps, double full_steps_per_s) {
    DynamicAxis axis(p);
    axis.on_enable(0, true);
    const double microstep_s = 1.0 / (full_steps_per_s * microsteps);
    const auto steps = std::max<std::int64_t>(static_cast<std::int64_t>(kPullInRunS / microstep_s), 20 * microsteps);
    for (std::int64_t k = 1; k <= steps; ++k) axis.on_microstep(s_to_ps(k * microstep_s), k, microsteps);
    // Settle for as long again, looking at the rotor ten times (a slip is counted when it is seen).
    for (int i = 1; i <= 10; ++i) (void)axis.shaft_angle_deg(s_to_ps(steps * microstep_s + i * kPullInRunS / 10));
    return axis.stats().lost_full_steps == 0;
}

double pull_in_rate(const AxisParams& p, int microsteps, double max_full_steps_per_s) {
    double pass = 0.0;
    double rate = kPullInStartHz;
    while (rate <= max_full_steps_per_s && starts_without_loss(p, microsteps, rate)) {
        pass = rate;
        rate *= 1.05;
    }
    if (rate > max_full_steps_per_s || pass == 0.0) return pass;
    double fail = rate;
    for (int i = 0; i < 6; ++i) {
        const double mid = 0.5 * (pass + fail);
        (starts_without_loss(p, microsteps, mid) ? pass : fail) = mid;
    }
    return pass;
}

}  // namespace cnc::mech
