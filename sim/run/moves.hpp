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
// each when it begins). `program` is null for a steps-file job: each segment's path is then its own straight line.
// Both must outlive this.
class CommandedMoves {
public:
    CommandedMoves(const host::Program* program, const std::vector<host::MotionSegment>& segments,
                   const host::MachineModel& machine, geom::Vec2 start_mm);
    [[nodiscard]] bool done() const { return m_next == m_segments.size(); }
    [[nodiscard]] metrics::MoveSpec next();  // not done()

private:
    const host::Program* m_program;
    const std::vector<host::MotionSegment>& m_segments;
    double m_mm_per_step_x, m_mm_per_step_y;
    geom::Vec2 m_start_mm;
    std::size_t m_next = 0;
    std::int64_t m_at_x = 0, m_at_y = 0;  // step counts before segment m_next
};

// All of them.
std::vector<metrics::MoveSpec> commanded_moves(const host::Program* program,
                                               const std::vector<host::MotionSegment>& segments,
                                               const host::MachineModel& machine, geom::Vec2 start_mm);

}  // namespace cnc::sim
