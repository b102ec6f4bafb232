// The atmega architecture (seed 003).
#pragma once
#include "run/arch_run.hpp"
#include "run/job.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

ArchRun run_atmega(const Scenario& scenario, const Job& job);

}  // namespace cnc::sim
