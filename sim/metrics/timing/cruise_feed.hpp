// The feed a programmed move achieved on a controller with a trajectory planner, where the planner's ramps and
// blends make the whole-move average meaningless: the path speed the STEP edges show over the move's cruise, the
// part of its window where the commanded path speed is at the programmed feed (docs/metrics.md "Feed error").
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "metrics/pulse/edge_index.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

// The commanded path speed counts as at F from (1 - kCruiseTolerance) x F: the planner's cruise is F itself, and
// this keeps no more than the last 0.1 % of a speed change in the cruise.
inline constexpr double kCruiseTolerance = 1e-3;

// First and last time, on a scan of [t_begin, t_end] at the trajectory's scan step, at which the commanded path
// speed is at least (1 - kCruiseTolerance) x speed; none if it never is (the planner held the move below F).
[[nodiscard]] std::optional<std::pair<TimePs, TimePs>> cruise_window(const CommandedTrajectory& c, TimePs t_begin_ps,
                                                                     TimePs t_end_ps, double speed_mm_per_s);

// The tool's step-count position along the run, edge by edge in time order: it serves the moves in time order,
// so a whole run costs one pass over its edges.
class StepPosition {
public:
    StepPosition(const RunInput& in, const EdgeIndex& idx);
    // Path length along `path` covered between the first and the last instant in [t_from, t_to] at which a STEP
    // rises (the position after every edge of that instant), with those instants; none with fewer than two.
    // Calls must come with non-decreasing t_from.
    struct Travel {
        double path_mm = 0.0;
        TimePs t_first_ps = 0;
        TimePs t_last_ps = 0;
    };
    [[nodiscard]] std::optional<Travel> travel(const geom::Segment& path, TimePs t_from_ps, TimePs t_to_ps);

private:
    void advance_before(TimePs t_ps);
    [[nodiscard]] geom::Vec2 position() const;

    const RunInput& m_in;
    const EdgeIndex& m_idx;
    std::vector<std::size_t> m_next;    // [axis] the first edge not yet counted
    std::vector<std::int64_t> m_count;  // [axis] net steps counted
};

}  // namespace cnc::metrics
