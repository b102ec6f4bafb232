#include "mechanics/core/axis_integrator.hpp"

#include <algorithm>
#include <array>
#include <cmath>

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

// Integrating factor (Lawson's method) for the windings whose bridge regulates at the start of a step: such a
// winding is integrated as z = (i - i_ref) exp(rate (t - t0)), which stays constant for as long as the bridge
// regulates (drv8825_current.hpp), so the current's decay at 1/tau + R/L (about 50,000 /s), stiff for an
// explicit method, costs no steps. A winding whose bridge sits at +-VMOT (its current ramps at L/R) has rate 0
// and is integrated as it is. The error control sees z: a bridge that stops regulating within the step makes
// z grow and the step shorten.
class CurrentFrame {
public:
    CurrentFrame(const AxisOde& ode, std::array<bool, 2> regulated, double t0_s)
        : m_t0_s(t0_s), m_regulated(regulated), m_rate_per_s(ode.regulation_rate_per_s()) {
        const WindingSetpoints& sp = ode.setpoints().current;
        m_offset_a = {m_regulated[0] ? sp.a_a : 0.0, m_regulated[1] ? sp.b_a : 0.0};
    }

    // The physical state and its derivative at t0 into the frame.
    void enter(AxisState& x, AxisState& dxdt) const {
        for (int k = 0; k < 2; ++k) {
            if (!m_regulated[k]) continue;
            const double w = x[k] - m_offset_a[k];
            x[k] = w;
            dxdt[k] += m_rate_per_s * w;
        }
    }
    // The frame's state and derivative at t back to physical ones.
    void leave(double t_s, AxisState& y, AxisState& dy) const {
        const double decay = std::exp(-m_rate_per_s * (t_s - m_t0_s));
        for (int k = 0; k < 2; ++k) {
            if (!m_regulated[k]) continue;
            const double w = y[k] * decay;
            y[k] = m_offset_a[k] + w;
            dy[k] = dy[k] * decay - m_rate_per_s * w;
        }
    }
    // The equations of motion in the frame.
    void derivative(const AxisOde& ode, const AxisState& y, AxisState& dy, double t_s) const {
        if (!m_regulated[0] && !m_regulated[1]) {
            ode(y, dy, t_s);
            return;
        }
        const double grow = std::exp(m_rate_per_s * (t_s - m_t0_s));
        AxisState x = y;
        for (int k = 0; k < 2; ++k) {
            if (m_regulated[k]) x[k] = m_offset_a[k] + y[k] / grow;
        }
        ode(x, dy, t_s);
        for (int k = 0; k < 2; ++k) {
            if (m_regulated[k]) dy[k] = (dy[k] + m_rate_per_s * (x[k] - m_offset_a[k])) * grow;
        }
    }

private:
    double m_t0_s;
    std::array<bool, 2> m_regulated;
    double m_rate_per_s;
    std::array<double, 2> m_offset_a{};
};

}  // namespace

AxisIntegrator::AxisIntegrator(const AxisParams& params, const IntegratorTolerances& tol)
    : m_ode(params), m_tol(tol), m_dt_s(std::min(1e-6, tol.max_step_s)) {}

void AxisIntegrator::set_setpoints(const AxisSetpoints& sp) {
    m_ode.set_setpoints(sp);
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

void AxisIntegrator::advance_to(double t_s) {
    if (t_s <= m_t_s) return;
    if (m_at_rest) {
        m_t_s = t_s;
        return;
    }
    auto stepper = odeint::make_controlled(m_tol.abs_tol, m_tol.rel_tol, Dopri5());
    if (!m_dxdt_valid) m_ode(m_x, m_dxdt, m_t_s);
    m_dxdt_valid = true;
    while (m_t_s < t_s) {
        const double remaining = t_s - m_t_s;
        const bool last = m_dt_s >= remaining;
        double dt = last ? remaining : m_dt_s;
        // A step across the end of a current ramp straddles a kink the error control would reject, step after
        // step: end it just past where the bridge is expected to regulate again (a tenth of the regulation's
        // time constant past it, so that the estimate, made at the step's start, cannot leave it short).
        const AxisOde::Bridges bridges = m_ode.bridges(m_x, m_dxdt);
        const double to_kink = bridges.time_to_regulation_s + 0.1 / m_ode.regulation_rate_per_s();
        const bool at_kink = to_kink < dt;
        if (at_kink) dt = to_kink;
        const CurrentFrame frame(m_ode, bridges.regulate, m_t_s);
        auto system = [this, &frame](const AxisState& y, AxisState& dy, double t) {
            frame.derivative(m_ode, y, dy, t);
        };
        AxisState y = m_x;
        AxisState dy = m_dxdt;
        frame.enter(y, dy);
        double t = m_t_s;
        if (stepper.try_step(system, y, dy, t, dt) == odeint::success) {
            ++m_steps;
            frame.leave(t, y, dy);
            m_x = y;
            m_dxdt = dy;
            m_t_s = last && !at_kink ? t_s : t;  // land exactly on the event time despite rounding
            // A step cut at a kink says nothing about the step size beyond it: keep the one from before.
            if (!at_kink && (!last || dt < m_dt_s)) m_dt_s = std::min(dt, m_tol.max_step_s);
        } else {
            m_dt_s = dt;
        }
    }
    m_at_rest = converged();
}

}  // namespace cnc::mech
