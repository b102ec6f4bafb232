#include "mechanics/core/axis_integrator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/external/eigen/eigen.hpp>

namespace cnc::mech {

struct AxisIntegrator::Dopri5
    : boost::numeric::odeint::runge_kutta_dopri5<AxisState, double, AxisState, double,
                                                 boost::numeric::odeint::vector_space_algebra> {};

namespace {

// Rest thresholds: below these the axis moves less than 1e-6 rad (0.001 of a 1/32 microstep) or 1 nm per
// second of fast-forward, and the currents sit within 10 uA of their set-points. The accelerations allow
// for the integration noise at the fixed point (state errors of ~1e-9 at the default tolerances): 1e-2
// rad/s2 is a torque imbalance of 3.4e-8 N m on the seed rotor, 5e-9 rad of its stiffness at 0.3 A.
constexpr double kRestOmegaRad_s = 1e-6;
constexpr double kRestAlphaRad_s2 = 1e-2;
constexpr double kRestVelocityM_s = 1e-9;
constexpr double kRestAccelM_s2 = 1e-5;
constexpr double kRestCurrentErrorA = 1e-5;
// A change of mode is placed within 100 ns: the DRV8825 decides its PWM on a far coarser time scale
// (its fixed off-time is about 30 us, SLVSA73 §7.6 tOFF).
constexpr double kModeSwitchResolutionS = 1e-7;

// odeint's error measure for a step from y (derivative dy) of length dt: the largest error relative to its
// tolerance, abs + rel (|y| + dt |dy|) (controlled_runge_kutta's default_error_checker).
double error_ratio(const AxisState& err, const AxisState& y, const AxisState& dy, double dt,
                   const IntegratorTolerances& tol) {
    return (err.array().abs() / (tol.abs_tol + tol.rel_tol * (y.array().abs() + dt * dy.array().abs()))).maxCoeff();
}

// The time in (t0, t1] at which margin(t) turns negative, given margin(t0) = m0 >= 0 > margin(t1) = m1:
// regula falsi with the Illinois modification, to kModeSwitchResolutionS. Each estimate is moved half the
// resolution towards the side the previous one did not land on, so that a good estimate closes the bracket
// at the next one. Returns the end of the bracket past the switch, so that the next step starts in the new
// modes.
template <class Margin>
double mode_switch_time_s(const Margin& margin, double t0, double m0, double t1, double m1) {
    int kept = 0;  // which end was kept last: -1 the early one, +1 the late one
    double bias = 0.5 * kModeSwitchResolutionS;
    while (t1 - t0 > kModeSwitchResolutionS) {
        const double t = std::clamp((t0 * m1 - t1 * m0) / (m1 - m0) + bias, t0 + 0.25 * kModeSwitchResolutionS,
                                    t1 - 0.25 * kModeSwitchResolutionS);
        const double m = margin(t);
        if (m < 0.0) {
            t1 = t;
            m1 = m;
            if (kept == -1) m0 *= 0.5;
            kept = -1;
            bias = -0.5 * kModeSwitchResolutionS;
        } else {
            t0 = t;
            m0 = m;
            if (kept == 1) m1 *= 0.5;
            kept = 1;
            bias = 0.5 * kModeSwitchResolutionS;
        }
    }
    return t1;
}

}  // namespace

AxisIntegrator::AxisIntegrator(const AxisParams& params, const IntegratorTolerances& tol)
    : m_ode(params), m_tol(tol), m_stepper(std::make_unique<Dopri5>()), m_dt_s(std::min(1e-6, tol.max_step_s)) {}

AxisIntegrator::~AxisIntegrator() = default;
AxisIntegrator::AxisIntegrator(AxisIntegrator&&) noexcept = default;

void AxisIntegrator::set_setpoints(const AxisSetpoints& sp) {
    m_ode.set_setpoints(sp);
    m_after_change = true;
    m_at_rest = false;
    m_front_valid = false;  // what lies beyond m_t_s followed the old set-points
    m_last.reset();
}

void AxisIntegrator::set_state(const AxisState& x) {
    m_x = x;
    m_at_rest = false;
    m_front_valid = false;
    m_last.reset();
}

bool AxisIntegrator::converged() const {
    const AxisState& x = m_front_x;
    const AxisState& d = m_front_dxdt;
    const WindingSetpoints& sp = m_ode.setpoints().current;
    return std::abs(x[kOmega]) < kRestOmegaRad_s && std::abs(d[kOmega]) < kRestAlphaRad_s2 &&
           std::abs(x[kV]) < kRestVelocityM_s && std::abs(d[kV]) < kRestAccelM_s2 &&
           std::abs(x[kIa] - sp.a_a) < kRestCurrentErrorA && std::abs(x[kIb] - sp.b_a) < kRestCurrentErrorA;
}

void AxisIntegrator::start_at(const AxisState& x, double t_s) {
    start_at(x, t_s, rotor_angle(m_ode.params().motor, x[kTheta]));
}

void AxisIntegrator::start_at(const AxisState& x, double t_s, RotorAngle angle) {
    m_front_x = x;
    m_front_t_s = t_s;
    m_front_angle = angle;
    m_front_modes = m_ode.modes(x, m_front_angle);
    m_ode.derivative(x, m_front_dxdt, m_front_modes, m_front_angle);
    m_front_valid = true;
}

AxisState AxisIntegrator::state_in_step(double t_s) const {
    if (t_s == m_front_t_s) return m_front_x;
    const Step& s = *m_last;
    AxisState y;
    m_stepper->calc_state(t_s, y, s.y0, s.dy0, s.t0_s, s.y1, s.dy1, s.t1_s);
    s.frame.leave(t_s, y);
    return y;
}

void AxisIntegrator::advance_to(double t_s) {
    if (t_s <= m_t_s) return;
    if (m_at_rest) {
        m_t_s = t_s;
        m_front_t_s = t_s;
        return;
    }
    if (!m_front_valid) start_at(m_x, m_t_s);
    while (m_front_t_s < t_s) step();
    m_x = state_in_step(t_s);
    m_t_s = t_s;
    m_at_rest = converged();
    if (m_at_rest) {
        // Fast-forward from here: the converged front stands for every later time.
        m_x = m_front_x;
        m_front_t_s = t_s;
        m_last.reset();
    }
}

void AxisIntegrator::step() {
    while (true) {
        if (m_after_change && m_dt_after_change_s > 0.0) m_dt_s = m_dt_after_change_s;
        const double dt = m_dt_s;
        const double t0 = m_front_t_s;
        const double t1 = t0 + dt;
        const CurrentFrame frame(m_ode, m_front_modes, m_front_x, m_front_angle, t0, dt);
        AxisState y0 = m_front_x;
        AxisState dy0 = m_front_dxdt;
        frame.enter(y0, dy0);
        AxisState y1;
        AxisState dy1;
        AxisState err;
        m_stepper->do_step(std::cref(frame), y0, dy0, t0, y1, dy1, dt, err);  // odeint copies a system per call
        const double ratio = error_ratio(err, y0, dy0, dt, m_tol);
        if (ratio > 1.0) {
            m_dt_s = m_step_control.next_step_s(dt, ratio);
            if (m_after_change) m_dt_after_change_s = m_dt_s;
            continue;
        }
        ++m_steps;
        m_dt_s = std::min(m_step_control.next_step_s(dt, ratio), m_tol.max_step_s);
        if (m_after_change) m_dt_after_change_s = m_dt_s;
        m_after_change = false;
        m_last.emplace(Step{frame, t0, t1, y0, dy0, y1, dy1});
        AxisState x1 = y1;
        AxisState dx1 = dy1;
        frame.leave(t1, x1, dx1);
        const AxisOde::ModeMargins margins1 = frame.mode_margins(x1);
        if (*std::min_element(margins1.begin(), margins1.end()) >= 0.0) {
            m_front_x = x1;
            m_front_dxdt = dx1;
            m_front_angle = frame.angle(x1[kTheta]);
            m_front_t_s = t1;
            return;
        }
        // A part changed mode within the step: the step is only valid up to there. Find the time on the
        // step's interpolant (Dormand-Prince's dense output) and start the next step from it, in the new modes.
        // The margin of the parts that left their modes (the others' would mislead the secant).
        auto crossed_margin = [&margins1](const AxisOde::ModeMargins& m) {
            double least = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < m.size(); ++k) {
                if (margins1[k] < 0.0) least = std::min(least, m[k]);
            }
            return least;
        };
        const double margin0 = crossed_margin(frame.mode_margins(m_front_x));
        m_front_x = x1;  // the interpolant's whole span, until the switch is found
        m_front_t_s = t1;
        auto margin_at = [&](double t) { return crossed_margin(frame.mode_margins(state_in_step(t))); };
        const double t_switch = mode_switch_time_s(margin_at, t0, margin0, t1, crossed_margin(margins1));
        const AxisState x_switch = state_in_step(t_switch);
        start_at(x_switch, t_switch, frame.angle(x_switch[kTheta]));
        return;
    }
}

}  // namespace cnc::mech
