// Path speed along one planned piece: rise from the entry speed to a peak, cruise, fall to the exit speed.
// Trapezoidal: each speed change at the constant path acceleration limit a.
// JerkLimited (seed 004 §3.2 "cubic acceleration", Osornio-Rios et al. 2009): the seed's rest-to-rest shape is
// the quintic position s = L p(tau), p = 10 tau^3 - 15 tau^4 + 6 tau^5 (cubic acceleration). Here the same p
// shapes every speed change, so moves can also be entered and left at speed: v0 -> v1 = v0 + dv over T seconds
// follows v(tau) = v0 + dv * p(tau), tau = t / T; the acceleration dv/T * 30 tau^2 (1 - tau)^2 starts and ends
// at 0, and the jerk is continuous too (position of degree 6, one above the seed's, as the price of that). Peaks: p' is largest at tau = 1/2, 15/8, so |a| <= 15/8 |dv| / T; |p''| = |60 tau (1 - tau)
// (1 - 2 tau)| is largest at tau = (3 -+ sqrt(3)) / 6, 10 / sqrt(3), so |jerk| <= 10/sqrt(3) |dv| / T^2. The
// shortest allowed T is therefore max(15/8 |dv| / a, sqrt(10/sqrt(3) |dv| / j)). Because p(tau) + p(1 - tau) = 1,
// both shapes cover (v0 + v1) / 2 * T of path. Acceleration is 0 at every piece boundary in this shape.
#pragma once
#include "host/core/planner/path_limits.hpp"
#include "host/core/planner/planner_config.hpp"

namespace cnc::host::planner {

struct PathState {
    double s_mm;
    double v_mm_per_s;
    double a_mm_per_s2;
};

double transition_time_s(Profile shape, double v0, double v1, const PathLimits& limits);
double transition_distance_mm(Profile shape, double v0, double v1, const PathLimits& limits);
// The highest speed v1 >= v0 that a speed rise starting at v0 can reach within distance_mm (ignoring the speed
// limit). By symmetry also the highest entry speed from which the piece can slow down to v0.
double reachable_speed(Profile shape, double v0, double distance_mm, const PathLimits& limits);

struct SpeedProfile {
    Profile shape = Profile::Trapezoidal;
    PathLimits limits{};
    double length_mm = 0.0;
    double entry_mm_per_s = 0.0;
    double peak_mm_per_s = 0.0;
    double exit_mm_per_s = 0.0;
    double rise_s = 0.0;    // entry -> peak
    double cruise_s = 0.0;  // at peak
    double fall_s = 0.0;    // peak -> exit

    [[nodiscard]] double duration_s() const { return rise_s + cruise_s + fall_s; }
    // State t seconds after the piece starts (t clamped to the piece; s clamped to its length).
    [[nodiscard]] PathState at(double t_s) const;
};

// Fastest profile over `length_mm` from entry to exit speed within `limits`; the caller guarantees that the
// change entry -> exit fits (transition_distance_mm <= length_mm, up to rounding).
SpeedProfile make_speed_profile(Profile shape, double length_mm, double entry_mm_per_s, double exit_mm_per_s,
                                const PathLimits& limits);

}  // namespace cnc::host::planner
