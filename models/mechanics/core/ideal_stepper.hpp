// A stepper whose shaft follows the commanded microstep instantly and exactly: no inertia, no load angle,
// no microstep non-linearity. The reference against which a dynamic model's errors are measured.
#pragma once
#include "mechanics/core/motor.hpp"

namespace cnc::mech {

class IdealStepper : public StepperMotor {
public:
    // step_angle_deg: mechanical degrees per full step (42BYGHW208: 1.8 deg, seed 000 §2.3).
    explicit IdealStepper(double step_angle_deg = 1.8);

    void on_microstep(TimePs t_ps, std::int64_t microstep_index, int microsteps_per_full_step) override;
    // An ideal motor holds its angle with the windings off (no external load moves it).
    void on_enable(TimePs, bool) override {}
    // angle = index * step_angle_deg / microsteps, as commanded at the last call.
    [[nodiscard]] double shaft_angle_deg(TimePs t_ps) const override;

private:
    double m_step_angle_deg;
    double m_angle_deg = 0.0;
};

}  // namespace cnc::mech
