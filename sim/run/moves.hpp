// What each executed motion command should have done, for the metrics: its programmed geometry, its own
// commanded end points and the per-axis step rates the programmed feed implies. Shared by every architecture
// that executes the host's motion segments; the architecture fills in the execution windows.
#pragma once
#include <vector>

#include "metrics/run_input.hpp"
#include "run/job.hpp"

namespace cnc::sim {

// `program` is null for a steps-file job: each segment's path is then its own straight line.
std::vector<metrics::MoveSpec> commanded_moves(const host::Program* program,
                                               const std::vector<host::MotionSegment>& segments,
                                               const host::MachineModel& machine, geom::Vec2 start_mm);

}  // namespace cnc::sim
