// Event-driven integration of one axis (axis_ode.hpp) with Boost.Odeint.
//
// Stepper: Dormand-Prince 5(4) (Boost.Odeint's runge_kutta_dopri5) under odeint's step-size rule, with
// absolute and relative error tolerances per step (IntegratorTolerances). The equations are piecewise smooth
// (a DRV8825 bridge regulates or sits at +-VMOT; a body is inside or outside its friction's stick band): each
// step holds the modes of its start (AxisModes), and a step at whose end they no longer hold is cut where they
// changed, found on the step's interpolant (Dormand-Prince's dense output), so that no step straddles a kink
// the error control would reject again and again. A winding whose bridge regulates is integrated through an
// integrating factor (Lawson's method, axis_integrator.cpp): its current's 20 us decay towards the set-point is
// exact, not stepped through. The set-points are constant between events,
// so the caller advances the state to each event time (a microstep change, an EN change, a sample) and
// then changes them; the integrator never steps past the time it is asked for. Once the axis has come to
// rest (speeds, accelerations and current errors below the rest thresholds) it is fast-forwarded: later
// calls move its clock without integrating, until the set-points change. The derivative at the end of the
// last step is kept between calls (Dormand-Prince's first-same-as-last stage) until the set-points or the
// state change.
#pragma once
#include <cstdint>

#include "mechanics/core/axis_ode.hpp"

namespace cnc::mech {

struct IntegratorTolerances {
    double abs_tol = 1e-8;     // per step, in the state's SI units (A, rad, rad/s, m, m/s)
    double rel_tol = 1e-4;    // the reports change by < 0.03 um against 1e-5 (docs/mechanics.md)
    double max_step_s = 1e-3;  // never step further than this, so the step control sees every transient
};

class AxisIntegrator {
public:
    explicit AxisIntegrator(const AxisParams& params, const IntegratorTolerances& tol = {});

    // Integrates from the current time to t_s (no-op if t_s is not later).
    void advance_to(double t_s);
    // New set-points from the current time on (ends a fast-forward).
    void set_setpoints(const AxisSetpoints& sp);
    // Replaces the state (initial conditions for tests and studies).
    void set_state(const AxisState& x);

    [[nodiscard]] double time_s() const { return m_t_s; }
    [[nodiscard]] const AxisState& state() const { return m_x; }
    [[nodiscard]] const AxisOde& ode() const { return m_ode; }
    [[nodiscard]] bool at_rest() const { return m_at_rest; }
    [[nodiscard]] std::int64_t steps_taken() const { return m_steps; }

private:
    [[nodiscard]] bool converged() const;
    // Continues from state x at time t, in the bridge modes of x.
    void start_at(const AxisState& x, double t_s);

    AxisOde m_ode;
    IntegratorTolerances m_tol;
    AxisState m_x = AxisState::Zero();
    AxisState m_dxdt = AxisState::Zero();  // at m_x, m_t_s when m_dxdt_valid
    AxisModes m_modes;                      // at m_x, m_t_s when m_dxdt_valid
    bool m_dxdt_valid = false;
    double m_t_s = 0.0;
    double m_dt_s;
    // Every set-point change starts a transient (a current ramp, the rotor's response) whose first step wants
    // about the size it wanted after the previous change, not the size the quiet end of the last one grew to.
    bool m_after_change = false;
    double m_dt_after_change_s = 0.0;
    bool m_at_rest = false;
    std::int64_t m_steps = 0;
};

}  // namespace cnc::mech
