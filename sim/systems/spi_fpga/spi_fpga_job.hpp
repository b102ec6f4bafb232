// The spi-fpga host's G-code job read from its file one move at a time (the Job holds only the program's summary,
// Architecture::streams_job), as fpga-uart's is: read ahead of the run, planned whole once (the planner's errors
// before anything is simulated, and the plan's rest points the report counts) and read again for the laser intent
// and the job estimate; during the run, planned again as the servo consumes it (open_plan).
#pragma once
#include <memory>

#include "host/core/planner/plan_feed.hpp"
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
JobAhead read_job_ahead(const Scenario& s, const Job& job, const ArchPace& pace);
// The job's plan, read from its file as far as it is asked for.
std::shared_ptr<host::planner::PlanFeed> open_plan(const Scenario& s);

}  // namespace cnc::sim
