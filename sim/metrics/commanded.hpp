// Helpers over a commanded timed trajectory (run_input.hpp): its state at a time, and the times at which one
// axis's commanded position crosses the half-step levels (what an ideal quantiser of that position would step at).
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "metrics/run_input.hpp"

namespace cnc::metrics {

// State at t, with t clamped to the trajectory's window.
[[nodiscard]] CommandedState commanded_at(const CommandedTrajectory& c, TimePs t_ps);

// Crossing times of one axis, to within 1 ps: up[n] lists when the commanded position, in steps from the origin, rises
// through n - 1/2 (a round-to-nearest quantiser steps to count n there), down[n] when it falls through n + 1/2.
// Each list is in time order.
struct StepCrossings {
    std::map<std::int64_t, std::vector<TimePs>> up;
    std::map<std::int64_t, std::vector<TimePs>> down;
    // The crossing of the step that brings the count to `count` in direction `sign` (+1/-1) nearest to t_ps.
    [[nodiscard]] std::optional<TimePs> nearest(std::int64_t count, int sign, TimePs t_ps) const;
};

// Scans [t_begin, t_end] at scan_step_ps, splits a scan interval where the axis velocity changes sign (at the
// turning point, found by bisection), and finds each crossing by safeguarded Newton iteration on the bracket.
// Only the scan intervals that overlap [from_ps, to_ps] are scanned (the crossings near a window of edges): a
// crossing there is found exactly as by the whole scan, since the intervals stay on the grid from t_begin.
[[nodiscard]] StepCrossings step_crossings(const CommandedTrajectory& c, std::size_t axis, double steps_per_mm,
                                           TimePs from_ps = std::numeric_limits<TimePs>::min(),
                                           TimePs to_ps = std::numeric_limits<TimePs>::max());

}  // namespace cnc::metrics
