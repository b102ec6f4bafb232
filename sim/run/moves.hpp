// What each executed motion command should have done, for the metrics: its programmed geometry, its own
// commanded end points and the per-axis step rates the programmed feed implies. Shared by every architecture
// that executes the host's motion segments; the architecture fills in the execution windows.
#pragma once
#include <cstddef>
#include <cstdint>
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

private:
    double m_mm_per_step_x, m_mm_per_step_y;
    geom::Vec2 m_start_mm;
    std::int64_t m_at_x = 0, m_at_y = 0;  // step counts before the next segment
};

// All of them. `program` is null for a steps-file job.
std::vector<metrics::MoveSpec> commanded_moves(const host::Program* program,
                                               const std::vector<host::MotionSegment>& segments,
                                               const host::MachineModel& machine, geom::Vec2 start_mm);

}  // namespace cnc::sim
