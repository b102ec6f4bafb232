// A G-code text planned as it is read (host::planner::PlanFeed), for the tests of the plan and its readers.
#pragma once
#include <memory>
#include <sstream>
#include <string>

#include "host/core/gcode.hpp"
#include "host/core/planner/plan_feed.hpp"

namespace cnc::test {

struct FedJob {
    FedJob(const std::string& gcode, const host::planner::PlannerConfig& cfg,
           const host::InterpreterOptions& opt = host::InterpreterOptions{})
        : text(gcode), plan(cfg, std::make_unique<host::GcodeStream>(text, "t.nc", opt, false)) {}
    std::istringstream text;  // read by the plan's stream: declared first, it outlives the plan
    host::planner::PlanFeed plan;
};

}  // namespace cnc::test
