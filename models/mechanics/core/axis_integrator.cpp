#include "mechanics/core/axis_integrator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/external/eigen/eigen.hpp>

namespace cnc::mech {

namespace {

namespace odeint = boost::numeric::odeint;
using Dopri5 = odeint::runge_kutta_dopri5<AxisState, double, AxisState, double, odeint::vector_space_algebra>;

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

// Integrating factor (Lawson's method) for the windings whose bridge regulates during a step: such a winding
// is integrated as z = (i - i_ref) exp(rate (t - t0)), which stays constant while the bridge regulates
// (drv8825_current.hpp), so the current's decay at 1/tau + R/L (about 50,000 /s), stiff for an explicit
// method, costs no steps. A winding whose bridge sits at +-VMOT (its current ramps at L/R) is integrated as
// it is.
class CurrentFrame {
public:
    CurrentFrame(const AxisOde& ode, const AxisModes& modes, const AxisState& x0, double t0_s)
        : m_ode(ode), m_modes(modes), m_angle(ode.params().motor, x0[kTheta]), m_t0_s(t0_s),
          m_rate_per_s(ode.regulation_rate_per_s()) {
        const WindingSetpoints& sp = ode.setpoints().current;
        m_offset_a = {regulated(0) ? sp.a_a : 0.0, regulated(1) ? sp.b_a : 0.0};
    }

    // The physical state and its derivative at t0 into the frame.
    void enter(AxisState& x, AxisState& dxdt) const {
        for (int k = 0; k < 2; ++k) {
            if (!regulated(k)) continue;
            const double w = x[k] - m_offset_a[k];
            x[k] = w;
            dxdt[k] += m_rate_per_s * w;
        }
    }
    // The frame's state at t back to the physical one.
    void leave(double t_s, AxisState& y) const {
        const double decay = std::exp(-m_rate_per_s * (t_s - m_t0_s));
        for (int k = 0; k < 2; ++k) {
            if (regulated(k)) y[k] = m_offset_a[k] + y[k] * decay;
        }
    }
    // The same for a state and its derivative.
    void leave(double t_s, AxisState& y, AxisState& dy) const {
        leave(t_s, y);
        for (int k = 0; k < 2; ++k) {
            if (regulated(k)) dy[k] = -m_rate_per_s * (y[k] - m_offset_a[k]);
        }
    }
    // The margins of the modes at a physical state within the step (axis_ode.hpp).
    [[nodiscard]] AxisOde::ModeMargins mode_margins(const AxisState& x) const {
        return m_ode.mode_margins(x, m_modes, m_angle.at(x[kTheta]));
    }
    // The equations of motion in the frame.
    void operator()(const AxisState& y, AxisState& dy, double t_s) const {
        if (!regulated(0) && !regulated(1)) {
            m_ode.derivative(y, dy, m_modes, m_angle.at(y[kTheta]));
            return;
        }
        AxisState x = y;
        leave(t_s, x);
        m_ode.derivative(x, dy, m_modes, m_angle.at(x[kTheta]));
        for (int k = 0; k < 2; ++k) {
            if (regulated(k)) dy[k] = 0.0;  // the decay is the frame's: d/dt (i - i_ref) = -rate (i - i_ref)
        }
    }

private:
    [[nodiscard]] bool regulated(int k) const { return m_modes.bridges[k] == BridgeMode::Regulating; }

    const AxisOde& m_ode;
    AxisModes m_modes;
    RotorAngleNear m_angle;  // the shaft moves little within a step
    double m_t0_s;
    double m_rate_per_s;
    std::array<double, 2> m_offset_a{};
};

// odeint's error measure for a step from y (derivative dy) of length dt: the largest error relative to its
// tolerance, abs + rel (|y| + dt |dy|) (controlled_runge_kutta's default_error_checker).
double error_ratio(const AxisState& err, const AxisState& y, const AxisState& dy, double dt,
                   const IntegratorTolerances& tol) {
    return (err.array().abs() / (tol.abs_tol + tol.rel_tol * (y.array().abs() + dt * dy.array().abs()))).maxCoeff();
}

// The step-size rule of odeint's controlled_runge_kutta for a 5(4) pair: shrink by err^(-1/3) (at most 5 x)
// after a rejected step, grow by err^(-1/5) (at most 5 x) after one with err < 0.5.
double next_step_s(double dt, double err) {
    if (err > 1.0) return dt * std::max(0.9 * std::pow(err, -1.0 / 3.0), 0.2);
    if (err < 0.5) return dt * 0.9 * std::pow(std::max(err, std::pow(5.0, -5.0)), -1.0 / 5.0);
    return dt;
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
    : m_ode(params), m_tol(tol), m_dt_s(std::min(1e-6, tol.max_step_s)) {}

void AxisIntegrator::set_setpoints(const AxisSetpoints& sp) {
    m_ode.set_setpoints(sp);
    m_after_change = true;
    m_at_rest = false;
    m_dxdt_valid = false;
}

void AxisIntegrator::set_state(const AxisState& x) {
    m_x = x;
    m_at_rest = false;
    m_dxdt_valid = false;
}

bool AxisIntegrator::converged() const {
    const AxisState& d = m_dxdt;
    const WindingSetpoints& sp = m_ode.setpoints().current;
    return std::abs(m_x[kOmega]) < kRestOmegaRad_s && std::abs(d[kOmega]) < kRestAlphaRad_s2 &&
           std::abs(m_x[kV]) < kRestVelocityM_s && std::abs(d[kV]) < kRestAccelM_s2 &&
           std::abs(m_x[kIa] - sp.a_a) < kRestCurrentErrorA && std::abs(m_x[kIb] - sp.b_a) < kRestCurrentErrorA;
}

void AxisIntegrator::start_at(const AxisState& x, double t_s) {
    m_x = x;
    m_t_s = t_s;
    m_modes = m_ode.modes(m_x);
    m_ode.derivative(m_x, m_dxdt, m_modes, rotor_angle(m_ode.params().motor, m_x[kTheta]));
    m_dxdt_valid = true;
}

void AxisIntegrator::advance_to(double t_s) {
    if (t_s <= m_t_s) return;
    if (m_at_rest) {
        m_t_s = t_s;
        return;
    }
    if (!m_dxdt_valid) start_at(m_x, m_t_s);
    Dopri5 stepper;
    while (m_t_s < t_s) {
        if (m_after_change && m_dt_after_change_s > 0.0) m_dt_s = m_dt_after_change_s;
        const double remaining = t_s - m_t_s;
        const bool last = m_dt_s >= remaining;
        const double dt = last ? remaining : m_dt_s;
        const double t0 = m_t_s;
        const double t1 = last ? t_s : t0 + dt;  // land exactly on the event time despite rounding
        const CurrentFrame frame(m_ode, m_modes, m_x, t0);
        AxisState y0 = m_x;
        AxisState dy0 = m_dxdt;
        frame.enter(y0, dy0);
        AxisState y1;
        AxisState dy1;
        AxisState err;
        stepper.do_step(frame, y0, dy0, t0, y1, dy1, dt, err);
        const double ratio = error_ratio(err, y0, dy0, dt, m_tol);
        if (ratio > 1.0) {
            m_dt_s = next_step_s(dt, ratio);
            if (m_after_change) m_dt_after_change_s = m_dt_s;
            continue;
        }
        ++m_steps;
        const double next = std::min(next_step_s(dt, ratio), m_tol.max_step_s);
        if (m_after_change && !last) m_dt_after_change_s = next;
        m_after_change = false;
        if (!last || next < m_dt_s) m_dt_s = next;
        AxisState x1 = y1;
        AxisState dx1 = dy1;
        frame.leave(t1, x1, dx1);
        const AxisOde::ModeMargins margins1 = frame.mode_margins(x1);
        if (*std::min_element(margins1.begin(), margins1.end()) >= 0.0) {
            m_x = x1;
            m_dxdt = dx1;
            m_t_s = t1;
            continue;
        }
        // A part changed mode within the step: the step is only valid up to there. Find the time on the
        // step's interpolant (Dormand-Prince's dense output) and start the next step from it, in the new modes.
        auto state_at = [&](double t) {
            AxisState y;
            stepper.calc_state(t, y, y0, dy0, t0, y1, dy1, t1);
            frame.leave(t, y);
            return y;
        };
        // The margin of the parts that left their modes (the others' would mislead the secant).
        auto crossed_margin = [&margins1](const AxisOde::ModeMargins& m) {
            double least = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < m.size(); ++k) {
                if (margins1[k] < 0.0) least = std::min(least, m[k]);
            }
            return least;
        };
        auto margin_at = [&](double t) { return crossed_margin(frame.mode_margins(state_at(t))); };
        const double t_switch = mode_switch_time_s(margin_at, t0, crossed_margin(frame.mode_margins(m_x)), t1,
                                                   crossed_margin(margins1));
        start_at(state_at(t_switch), t_switch);
    }
    m_at_rest = converged();
}

}  // namespace cnc::mech
