// Sync error (docs/metrics.md "Pulse timing"): each rising STEP edge of a move against the time the commanded motion
// reaches that step. Drift from a truncated or quantised period shows up here although TIE does not see it.
// Without a commanded trajectory the commanded motion is uniform at the move's per-axis rate from its first step;
// with one (RunInput::commanded, a planner's profile) it is that trajectory: the edge that brings an axis's count
// to n is compared with the nearest time at which the commanded position crosses n - 1/2 going up (n + 1/2 going
// down), where a round-to-nearest quantiser of the commanded position would step; an edge with no such crossing
// within CommandedTrajectory::sync_window_ps is counted as unmatched.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "metrics/pulse/edge_index.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

struct SyncResult {
    std::vector<std::vector<std::optional<double>>> move_axis_max_abs_ns;  // [move][axis]
    std::vector<std::optional<double>> axis_max_abs_ns;                    // [axis]
    std::optional<double> max_abs_ns;
    // Commanded trajectory only: per axis, edges with no crossing of their step within its sync window.
    std::vector<std::optional<std::size_t>> axis_unmatched_edges;     // [axis]
    std::vector<std::vector<std::size_t>> move_axis_unmatched_edges;  // [move][axis]
};

// Uniform: edge k (k = 0..n-1) of a move on an axis is compared with t0 + k / rate_steps_per_s[axis], t0 = the
// move's first rising edge on any axis. Axes without a commanded rate (>= 2, or rate 0) are skipped.
// Trajectory: axes 0 and 1 with steps_per_mm > 0; counts start at 0 with the first edge of the run.
[[nodiscard]] SyncResult compute_sync(const RunInput& in, const EdgeIndex& idx);

}  // namespace cnc::metrics
