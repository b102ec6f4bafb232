// Scenario keys of the ideal architecture: the trajectory planner's ([planner], planner/planner_settings.hpp, the
// same keys and trajectory as every architecture that plans), on the machine's limits.
#pragma once
#include "architectures/architecture.hpp"
#include "host/core/planner/planner_config.hpp"

namespace cnc::sim {

struct IdealSettings final : ArchSettings {
    host::planner::PlannerConfig planner;
};

}  // namespace cnc::sim
