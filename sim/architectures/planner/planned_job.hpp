// The job as a host with a trajectory planner runs it: planned as it is read (host::planner::PlanFeed), and the
// planner's side of the job estimate.
#pragma once
#include <functional>
#include <memory>

#include "host/core/planner/plan_feed.hpp"
#include "host/core/planner/planner_config.hpp"
#include "run/job.hpp"
#include "run/job_estimate.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

// The job's plan, read from its file as far as it is asked for.
[[nodiscard]] std::shared_ptr<host::planner::PlanFeed> open_plan(const Scenario& s,
                                                                 const host::planner::PlannerConfig& cfg);

// The planner's side of the job estimate: the planner holds each axis to its velocity limit, and a move that
// starts and ends at rest (exact stop; blended corners are faster) spends the time of one speed change from rest
// beyond length / speed. That change is taken at the smallest tangential acceleration the planner uses (half the
// smaller axis limit, on arcs: path_limits.hpp) and the smaller jerk limit.
[[nodiscard]] ArchPace planner_pace(const host::planner::PlannerConfig& cfg);

// The job's estimate at the planner's pace, its moves read from the file once more (the job keeps none when it is
// streamed); `each` (may be empty) sees every programmed move as it is read.
[[nodiscard]] JobEstimate planned_estimate(const Scenario& s, const Job& job, const host::planner::PlannerConfig& cfg,
                                           const std::function<void(const host::ProgrammedMove&)>& each = {});

}  // namespace cnc::sim
