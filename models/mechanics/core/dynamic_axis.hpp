// A physical axis behind the StepperMotor interface: the DRV8825's currents, the hybrid stepper and its
// load (axis_ode.hpp), integrated event by event (axis_integrator.hpp).
//
// Every call advances the model to its time first (models only integrate forward: motor.hpp), so the
// const queries update a cached state. Lost steps: the rotor's electrical angle is compared with the
// commanded one at every call; once it lags or leads by more than half an electrical period it has fallen
// into another stable position, 4 full steps (one electrical period) away, and each such slip is counted
// with its time (not while the driver is disabled: the rotor is then free, and the count restarts from
// wherever it is held when the driver is enabled again).
#pragma once
#include <cstdint>
#include <vector>

#include "common/units.hpp"
#include "mechanics/core/axis_integrator.hpp"
#include "mechanics/core/carriage_drive.hpp"
#include "mechanics/core/motor.hpp"
#include "mechanics/core/peak_trace.hpp"

namespace cnc::mech {

struct LostStepEvent {
    TimePs t_ps = 0;
    int full_steps = 0;  // > 0: the rotor fell behind the command; < 0: it ran ahead
};

struct DynamicAxisStats {
    std::int64_t lost_full_steps = 0;   // sum of |full_steps| over the events
    std::vector<LostStepEvent> events;  // the first kMaxLostStepEvents, in time order
    double peak_load_angle_deg = 0.0;   // electrical degrees between command and rotor (90 = pull-out)
    TimePs peak_load_angle_ps = 0;
    PeakTrace load_angle_deg_trace;  // the load angle's peaks over time (the plots' load-angle curve)
    // Carriage velocity against the commanded one (a microstep over the time since the previous one), at
    // every microstep: RMS and peak of the difference, mm/s.
    double velocity_ripple_rms_mm_s = 0.0;
    double velocity_ripple_peak_mm_s = 0.0;
    std::int64_t ripple_samples = 0;
};

class DynamicAxis : public StepperMotor, public CarriageDrive {
public:
    static constexpr std::size_t kMaxLostStepEvents = 1000;

    explicit DynamicAxis(const AxisParams& params, const IntegratorTolerances& tol = {});

    void on_microstep(TimePs t_ps, std::int64_t microstep_index, int microsteps_per_full_step) override;
    void on_enable(TimePs t_ps, bool enabled) override;
    [[nodiscard]] double shaft_angle_deg(TimePs t_ps) const override;

    // Carriage position (mm from 0) and speed (mm/s) at t; with DriveKind::Free, the shaft's travel.
    [[nodiscard]] double carriage_mm(TimePs t_ps) const override;
    [[nodiscard]] bool at_rest() const override { return m_integrator.at_rest(); }
    [[nodiscard]] double carriage_velocity_mm_s(TimePs t_ps) const;
    // The shaft angle the driver commands (what an ideal motor would be at), deg.
    [[nodiscard]] double commanded_shaft_deg() const;
    // A torque on the shaft from outside, from t on.
    void set_external_torque(TimePs t_ps, double torque_nm);

    [[nodiscard]] const DynamicAxisStats& stats() const { return m_stats; }
    [[nodiscard]] const AxisIntegrator& integrator() const { return m_integrator; }

private:
    void advance(TimePs t_ps) const;
    void track_load_angle(TimePs t_ps) const;
    // Command minus rotor, electrical radians (> 0: the rotor lags).
    [[nodiscard]] double lag_electrical_rad() const;
    void apply_setpoints();
    void track_ripple(TimePs t_ps, std::int64_t previous_units);

    mutable AxisIntegrator m_integrator;
    mutable DynamicAxisStats m_stats;
    mutable std::int64_t m_slip_periods = 0;  // electrical periods the rotor has slipped (signed)
    mutable TimePs m_tracked_ps = -1;         // the time of the last advance, until the command moves
    std::int64_t m_units = 0;                 // commanded indexer position, 1/32 step
    TimePs m_last_microstep_ps = -1;
    double m_ripple_sum_sq = 0.0;
    bool m_enabled = false;
    double m_external_torque_nm = 0.0;
};

}  // namespace cnc::mech
