// Per-move timing: motion time, achieved feed against the programmed F, dead time between moves,
// and the job totals (DESIGN.md §4 "Feed error", "Job timing").
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "metrics/edge_index.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

struct MoveTiming {
    // From the move's first rising edge to its last one plus the period that edge closes (latest over the axes;
    // an axis with one edge: its commanded period), so a constant-period run of n edges takes exactly n periods;
    // cut at the next move's first edge and at the job's end, so that motion never exceeds the job.
    std::optional<double> motion_time_s;
    std::optional<double> achieved_feed_mm_per_min;  // |to_mm - from_mm| / motion time (cutting moves)
    std::optional<double> feed_error_pct;            // (achieved - F) / F
};

struct DeadGap {
    std::size_t after_move = 0;   // index into the move list
    std::size_t before_move = 0;
    TimePs dead_ps = 0;           // first rising edge of before_move - last rising edge of after_move (any axis)
};

struct TimingResult {
    std::vector<MoveTiming> moves;
    std::size_t feed_moves = 0;  // cutting moves with a feed error
    std::optional<double> feed_error_mean_pct;      // signed mean over cutting moves
    std::optional<double> feed_error_mean_abs_pct;
    std::optional<double> feed_error_max_abs_pct;
    double job_time_s = 0.0;                        // t_job_end - t_job_start
    std::optional<double> motion_time_s;            // sum of the per-move motion times
    std::vector<DeadGap> gaps;                      // between consecutive moves that emit steps
    std::optional<double> dead_total_ms, dead_mean_ms, dead_max_ms;
    std::optional<double> lead_in_ms;  // job start to the first rising STEP edge (any axis)
    std::optional<double> tail_ms;     // last rising STEP edge to the job end
};

[[nodiscard]] TimingResult compute_timing(const RunInput& in, const EdgeIndex& idx);

}  // namespace cnc::metrics
