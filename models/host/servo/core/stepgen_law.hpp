// The rate law of the host's step generator driver, in steps: LinuxCNC's hostmot2 stepgen position controller
// (src/hal/drivers/mesa-hostmot2/stepgen.c, hm2_stepgen_instance_position_control, "first-order feedforward and
// proportional error feedback ... based on John Kasunich's software stepgen"), once per servo period:
//   ff_vel         = (pos_cmd - old_pos_cmd) / T                      (feed-forward: the command's own velocity)
//   t_match        = |vel_fb - ff_vel| / A                             (time to match it at the accel limit A)
//   pos_at_match   = pos_fb + (ff_vel + vel_fb) / 2 * (t_match + T)    (where the axis will be then)
//   err_at_match   = pos_at_match - (pos_cmd + ff_vel * t_match)
//   t_match < T:   vel = ff_vel - gain * err_at_match / T, within vel_fb +- A T     (hm2: gain 0.5)
//   otherwise:     vel = vel_fb +- A T, towards the side that reduces |err_at_match| (hm2's ramp choice)
//   then |vel| <= max velocity.
// vel_fb is the velocity commanded in the previous period (hm2 feeds its own output back; here the rate of the
// word actually sent, i.e. after period rounding). The law aims the axis at pos_cmd one period after it was
// commanded (pos_at_match looks T ahead of pos_fb), so the axis follows its command with one servo period of lag:
// following error ~ velocity x T, the quantity LinuxCNC's FERROR/MIN_FERROR scale with speed.
// Deadband (LinuxCNC software stepgen: "if the error is tiny, just match velocity"; Remora's `deadband`, default
// 1 step): with |err_at_match| <= deadband the law commands ff_vel alone. The step counter only
// tells whole steps, so an estimate swings by one step as the generator's phase turns; a deadband below that
// would chase the swing every few periods and never hold a constant rate.
#pragma once

namespace cnc::host::servo {

struct StepgenParams {
    double max_velocity_steps_per_s = 0.0;  // > 0
    double max_accel_steps_per_s2 = 0.0;    // > 0
    double position_gain = 0.5;             // hm2: 0.5 * error / period; 1 = correct it all in one period
    double deadband_steps = 1.0;
};

struct StepgenState {
    double old_pos_cmd_steps = 0.0;
    double vel_fb_steps_per_s = 0.0;
};

struct StepgenOutput {
    double velocity_steps_per_s = 0.0;
    double err_at_match_steps = 0.0;
    bool in_deadband = false;
};

// One period of the law. Updates state.old_pos_cmd; the caller sets state.vel_fb to the rate it sends.
StepgenOutput stepgen_velocity(const StepgenParams& p, StepgenState& state, double pos_cmd_steps, double pos_fb_steps,
                               double period_s);

}  // namespace cnc::host::servo
