#include "host/servo/core/stepgen_law.hpp"

#include <algorithm>
#include <cmath>

namespace cnc::host::servo {

StepgenOutput stepgen_velocity(const StepgenParams& p, StepgenState& state, double pos_cmd_steps, double pos_fb_steps,
                               double period_s) {
    const double dt = period_s;
    const double a = p.max_accel_steps_per_s2;
    const double vel_fb = state.vel_fb_steps_per_s;
    const double ff_vel = (pos_cmd_steps - state.old_pos_cmd_steps) / dt;
    state.old_pos_cmd_steps = pos_cmd_steps;

    const double velocity_error = vel_fb - ff_vel;
    double match_accel = velocity_error > 0.0 ? -a : (velocity_error < 0.0 ? a : 0.0);
    const double t_match = match_accel == 0.0 ? 0.0 : -velocity_error / match_accel;
    const double avg_v = (ff_vel + vel_fb) * 0.5;
    const double pos_at_match = pos_fb_steps + avg_v * (t_match + dt);
    const double pos_cmd_at_match = pos_cmd_steps + ff_vel * t_match;

    StepgenOutput out;
    out.err_at_match_steps = pos_at_match - pos_cmd_at_match;
    double vel = 0.0;
    if (t_match < dt) {
        out.in_deadband = std::fabs(out.err_at_match_steps) <= p.deadband_steps;
        vel = out.in_deadband ? ff_vel : ff_vel - p.position_gain * out.err_at_match_steps / dt;
        vel = std::clamp(vel, vel_fb - a * dt, vel_fb + a * dt);
    } else {
        // hm2: ramping the other way for one period changes the position at match by 2 dp; take the ramp
        // direction that leaves the smaller error.
        const double dp = -2.0 * match_accel * dt * t_match;
        if (std::fabs(out.err_at_match_steps + 2.0 * dp) < std::fabs(out.err_at_match_steps)) {
            match_accel = -match_accel;
        }
        vel = vel_fb + match_accel * dt;
    }
    out.velocity_steps_per_s = std::clamp(vel, -p.max_velocity_steps_per_s, p.max_velocity_steps_per_s);
    return out;
}

}  // namespace cnc::host::servo
