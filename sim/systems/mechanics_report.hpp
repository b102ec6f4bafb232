// The dynamic mechanics' section of a run's report: per axis the lost steps (with their times), the peak
// load angle and the velocity ripple, and the laser's exposure per mm of the path the carriage followed.
// Nothing is added with the ideal mechanics.
#pragma once
#include "metrics/laser_exposure.hpp"
#include "run/arch_run.hpp"
#include "systems/machine.hpp"

namespace cnc::sim {

// Adds details["mechanics"] and a summary section; `exposure`: the laser's, as the streaming metrics folded it.
void add_mechanics_report(const Machine& machine, const metrics::LaserExposure& exposure, ArchRun& run);
// The same after run.input.tool and run.input.laser are set (the whole run kept), the exposure computed from them.
void add_mechanics_report(const Machine& machine, ArchRun& run);

}  // namespace cnc::sim
