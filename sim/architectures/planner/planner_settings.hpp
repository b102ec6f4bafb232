// The [planner] keys: the trajectory planner that a host with one runs on the job (seed 004's, and the ideal
// controller's), read by one reader for every architecture that plans, so that each plans the same trajectory.
#pragma once
#include "host/core/machine.hpp"
#include "host/core/planner/planner_config.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

// Reads the keys (registering their documentation); the axis limits are the machine's (machine.<axis>.max_*).
void read_planner_settings(KeyReader& r, const host::MachineModel& machine, host::planner::PlannerConfig& c);

}  // namespace cnc::sim
