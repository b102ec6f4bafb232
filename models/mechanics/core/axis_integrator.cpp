#include "mechanics/core/axis_integrator.hpp"

#include <algorithm>
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
    auto system = [this](const AxisState& x, AxisState& dxdt, double t) { m_ode(x, dxdt, t); };
    if (!m_dxdt_valid) m_ode(m_x, m_dxdt, m_t_s);
    m_dxdt_valid = true;
    while (m_t_s < t_s) {
        const double remaining = t_s - m_t_s;
        const bool last = m_dt_s >= remaining;
        double dt = last ? remaining : m_dt_s;
        if (stepper.try_step(system, m_x, m_dxdt, m_t_s, dt) == odeint::success) {
            ++m_steps;
            if (last) m_t_s = t_s;  // land exactly on the event time despite rounding
            if (!last || dt < m_dt_s) m_dt_s = std::min(dt, m_tol.max_step_s);
        } else {
            m_dt_s = dt;
        }
    }
    m_at_rest = converged();
}

}  // namespace cnc::mech
