// Event-driven integration of one axis (axis_ode.hpp) with Boost.Odeint.
//
// Stepper: Dormand-Prince 5(4) (Boost.Odeint's runge_kutta_dopri5) under odeint's error measure with
// absolute and relative error tolerances per step (IntegratorTolerances) and DOPRI5's PI step-size control
// (step_size_control.hpp). The equations are piecewise smooth
// (a DRV8825 bridge regulates or sits at +-VMOT; a body is inside or outside its friction's stick band): each
// step holds the modes of its start (AxisModes), and a step at whose end they no longer hold is cut where they
// changed, found on the step's interpolant (Dormand-Prince's dense output), so that no step straddles a kink
// the error control would reject again and again. A winding whose bridge regulates is integrated through an
// integrating factor (Lawson's method, current_frame.hpp): its current's 20 us decay towards the set-point is
// exact, not stepped through. The set-points are constant between events, so the caller advances the state
// to each event time (a microstep change, an EN change, a sample) and then changes them. The integrator does
// not shorten a step to land on the time it is asked for: it takes the steps its error control chooses until
// one spans that time and answers from the step's interpolant, so that a query (a sample, the other axis's
// step) costs no step. A set-point change drops what lies beyond its time and continues from the
// interpolated state there, as a mode change does. Once the axis has come to rest (speeds, accelerations and
// current errors below the rest thresholds) it is fast-forwarded: later calls move its clock without
// integrating, until the set-points change. The derivative at the end of the last step is kept between calls
// (Dormand-Prince's first-same-as-last stage) until the set-points or the state change.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>

#include "mechanics/core/axis_ode.hpp"
#include "mechanics/core/current_frame.hpp"
#include "mechanics/core/integrator_tolerances.hpp"
#include "mechanics/core/step_size_control.hpp"

namespace cnc::mech {

class AxisIntegrator {
public:
    explicit AxisIntegrator(const AxisParams& params, const IntegratorTolerances& tol = {});
    ~AxisIntegrator();
    AxisIntegrator(AxisIntegrator&&) noexcept;

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
    // Boost.Odeint's runge_kutta_dopri5, defined where it is used: odeint is the heaviest header of the build.
    struct Dopri5;

    [[nodiscard]] bool converged() const;
    // Continues from state x at time t, in the modes of x (`angle`: the rotor angle of x, if known from the
    // step that spans t; else the libm's, which also ends the carried angle's rounding drift at each
    // set-point change).
    void start_at(const AxisState& x, double t_s);
    void start_at(const AxisState& x, double t_s, RotorAngle angle);
    // One accepted step from the front (a rejected try is retried smaller).
    void step();
    // The state at t within the last step (its interpolant, or its end).
    [[nodiscard]] AxisState state_in_step(double t_s) const;

    AxisOde m_ode;
    IntegratorTolerances m_tol;
    std::unique_ptr<Dopri5> m_stepper;  // keeps the stages of the last step for its dense output
    // The state the caller sees, at the time it last asked for.
    AxisState m_x = AxisState::Zero();
    double m_t_s = 0.0;
    // The front of the integration (the end of the last step, or a mode change within it), at or after m_t_s.
    AxisState m_front_x = AxisState::Zero();
    AxisState m_front_dxdt = AxisState::Zero();  // when m_front_valid
    AxisModes m_front_modes;                     // when m_front_valid
    RotorAngle m_front_angle;                    // of m_front_x, when m_front_valid
    double m_front_t_s = 0.0;
    bool m_front_valid = false;
    // The last accepted step, in its current frame, valid from t0 up to the front.
    struct Step {
        CurrentFrame frame;
        double t0_s;
        double t1_s;
        AxisState y0;
        AxisState dy0;
        AxisState y1;
        AxisState dy1;
    };
    std::optional<Step> m_last;
    StepSizeControl m_step_control;
    double m_dt_s;
    // Every set-point change starts a transient (a current ramp, the rotor's response) whose first step wants
    // about the size it wanted after the previous change, not the size the quiet end of the last one grew to.
    bool m_after_change = false;
    double m_dt_after_change_s = 0.0;
    bool m_at_rest = false;
    std::int64_t m_steps = 0;
};

}  // namespace cnc::mech
