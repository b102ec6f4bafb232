// The dynamic mechanics' section of a run's report: per axis the lost steps (with their times), the peak
// load angle and the velocity ripple, and the laser's exposure per mm of the path the carriage followed.
// Nothing is added with the ideal mechanics.
#pragma once
#include <optional>

#include "run/arch_run.hpp"
#include "run/machine.hpp"
#include "run/metrics_feed.hpp"

namespace cnc::sim {

// Adds details["mechanics"] and a summary section. The laser's exposure: as `feed`, the run's streaming metrics,
// folded it; without a feed (the whole run kept) computed from run.input.tool and run.input.laser, set by then.
void add_mechanics_report(const Machine& machine, const std::optional<MetricsFeed>& feed, ArchRun& run);

}  // namespace cnc::sim
