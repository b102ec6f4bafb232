#include "host/servo/core/servo_config.hpp"

namespace cnc::host::servo {

double period_s(const ServoConfig& cfg) {
    return ps_to_s(cfg.period_ps);
}

StepgenParams stepgen_params(const ServoConfig& cfg, std::size_t axis) {
    const AxisServoConfig& a = cfg.axes[axis];
    const double k = (1.0 + cfg.stepgen_margin) * a.steps_per_mm;
    return StepgenParams{a.max_velocity_mm_per_s * k, a.max_accel_mm_per_s2 * k, cfg.position_gain, cfg.deadband_steps};
}

std::uint32_t landing_period_cycles(const ServoConfig& cfg) {
    return static_cast<std::uint32_t>(2 * cfg.period_ps / (kPsPerSec / static_cast<TimePs>(cfg.clk_hz)));
}

}  // namespace cnc::host::servo
