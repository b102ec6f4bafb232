// What `cncsim sweep` checks before any point runs: every key the sweep file sets or varies is a scenario key, every
// architecture exists, and each point's scenario loads (its job read against its machine) as its `cncsim run` child
// would load it, so that a value out of its key's range is named by the sweep file's line and key.
#pragma once
#include <vector>

#include "compare/compare_check.hpp"
#include "sweep/sweep_file.hpp"
#include "sweep/sweep_points.hpp"

namespace cnc::sim {

// Throws BadInput naming the sweep file's line and key. The points of one architecture and values are loaded once,
// with their first seed (the seeds are integers >= 0, which scenario.seed takes).
void check_sweep(const SweepSpec& spec, const std::vector<SweepPoint>& points, const CompareInput& input);

}  // namespace cnc::sim
