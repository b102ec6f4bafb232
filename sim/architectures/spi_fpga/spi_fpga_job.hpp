// The spi-fpga host's G-code job read from its file one move at a time (the Job holds only the program's summary,
// JobUse::streams_job): read ahead of the run, planned whole once (the planner's errors before anything is
// simulated, and the plan's rest points the report counts) and read again for the laser intent and the job
// estimate; during the run, planned again as the servo consumes it (planner/planned_job.hpp: open_plan).
#pragma once
#include "host/servo/core/servo_core.hpp"
#include "run/job.hpp"
#include "run/job_estimate.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

struct JobAhead {
    host::servo::ServoJob servo;
    JobEstimate estimate;
};

// BadInput for what the planner refuses (a cutting move without a positive feed).
JobAhead read_job_ahead(const Scenario& s, const Job& job, const host::planner::PlannerConfig& cfg);

}  // namespace cnc::sim
