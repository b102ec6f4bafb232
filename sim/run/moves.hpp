// What each executed motion command should have done, for the metrics: its programmed geometry, its own
// commanded end points and the per-axis step rates the programmed feed implies. Shared by every architecture
// that executes the host's motion segments; the architecture fills in the execution windows.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "metrics/run_input.hpp"
#include "run/job.hpp"

namespace cnc::sim {

// The moves one at a time in execution order, so that a long job's run need not hold them all (the metrics take
// each when it begins).
class CommandedMoves {
public:
    CommandedMoves(const host::MachineModel& machine, geom::Vec2 start_mm);
    // The next executed segment's move. `programmed` is the programmed move it belongs to; null for a steps-file
    // row, whose path is its own straight line.
    [[nodiscard]] metrics::MoveSpec next(const host::MotionSegment& seg, const host::ProgrammedMove* programmed);
    // Programmed move number `move` (0-based), too short for one microstep on every axis: it makes no segment, so
    // no controller runs it, but the metrics record it (docs/metrics.md "Per move"): zero steps where the tool is,
    // piece index 0, its window to be placed by place_unstepped().
    [[nodiscard]] metrics::MoveSpec unstepped(const host::ProgrammedMove& programmed, int move);

private:
    double m_mm_per_step_x, m_mm_per_step_y;
    geom::Vec2 m_start_mm;
    std::int64_t m_at_x = 0, m_at_y = 0;  // step counts before the next segment
};

// Sets the move's path feed F and its commanded per-axis step rates: F split over the axes in proportion to the
// move's own displacement (from_mm to to_mm, steps; docs/metrics.md "Commanded rate"). A move of no length keeps none.
void set_path_feed(metrics::MoveSpec& m, double feed_mm_per_min);

// A move of unstepped(): piece index 0.
[[nodiscard]] inline bool is_unstepped(const metrics::MoveSpec& m) { return m.index == 0 && m.programmed >= 0; }

// An unstepped move's window: the instant the next piece begins, so that it owns no STEP edge (the metrics give a
// piece the edges from its begin to the next piece's); with no piece after it, the instant after the last piece's
// window ends (`next_begin_ps` none, `last_end_ps` that end).
void place_unstepped(metrics::MoveSpec& m, std::optional<TimePs> next_begin_ps, TimePs last_end_ps);

// All of them, the unstepped programmed moves among them in program order. `program` is null for a steps-file job.
std::vector<metrics::MoveSpec> commanded_moves(const host::Program* program,
                                               const std::vector<host::MotionSegment>& segments,
                                               const host::MachineModel& machine, geom::Vec2 start_mm);

}  // namespace cnc::sim
