// Sync error: each rising STEP edge of a move against the time the commanded motion reaches that step,
// uniform at the commanded per-axis rate from the move's first step (DESIGN.md §4). Drift from a
// truncated or quantised period shows up here although TIE does not see it.
#pragma once
#include <optional>
#include <vector>

#include "metrics/edge_index.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

struct SyncResult {
    std::vector<std::vector<std::optional<double>>> move_axis_max_abs_ns;  // [move][axis]
    std::vector<std::optional<double>> axis_max_abs_ns;                    // [axis]
    std::optional<double> max_abs_ns;
};

// Edge k (k = 0..n-1) of a move on an axis is compared with t0 + k / rate_steps_per_s[axis], t0 = the
// move's first rising edge on any axis. Axes without a commanded rate (>= 2, or rate 0) are skipped.
[[nodiscard]] SyncResult compute_sync(const RunInput& in, const EdgeIndex& idx);

}  // namespace cnc::metrics
