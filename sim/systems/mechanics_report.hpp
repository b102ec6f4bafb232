// The dynamic mechanics' section of a run's report: per axis the lost steps (with their times), the peak
// load angle and the velocity ripple, and the laser's exposure per mm of the path the carriage followed.
// Nothing is added with the ideal mechanics.
#pragma once
#include "run/arch_run.hpp"
#include "systems/machine.hpp"

namespace cnc::sim {

// Call after run.input.tool and run.input.laser are set; adds details["mechanics"] and a summary section.
void add_mechanics_report(const Machine& machine, ArchRun& run);

}  // namespace cnc::sim
