// Per programmed move timing: motion time, achieved feed against the programmed F, dead time between programmed
// moves and inside them (between their pieces), and the job totals (definitions in docs/metrics.md "Feed error",
// "Job timing").
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "metrics/pulse/edge_index.hpp"
#include "metrics/run_input.hpp"
#include "metrics/timing/programmed_moves.hpp"

namespace cnc::metrics {

struct DeadGap {
    std::size_t after_move = 0;  // index into the programmed moves
    std::size_t before_move = 0;
    TimePs dead_ps = 0;  // first rising edge of before_move - last rising edge of after_move (any axis)
};

struct MoveTiming {
    // From the programmed move's first rising edge to its last one plus the period that edge closes (latest over
    // the axes; an axis with one edge: its commanded period), so a constant-period run of n edges takes exactly n
    // periods; cut at the next programmed move's first edge and at the job's end, so that motion never exceeds
    // the job. The pauses between the pieces of a move (an arc's chords) are part of its motion time.
    std::optional<double> motion_time_s;
    // Cutting moves. Without a planner: programmed path length / motion time. With a planner (RunInput::commanded):
    // the path speed of the STEP edges over the cruise (cruise_feed.hpp); none where the commanded speed never
    // reaches F.
    std::optional<double> achieved_feed_mm_per_min;
    std::optional<double> feed_error_pct;  // (achieved - F) / F
    bool below_feed = false;               // planner: a cutting move whose commanded speed never reached F
    // The dead-time gap that ends at this move's first edge, from the last edge of the previous programmed move
    // with edges (`dead_after_move`, index into the programmed moves); none for the first move with edges and
    // moves without. Kept with the move, so that the gaps of a long job are spilled with its moves (MoveRecords).
    std::optional<std::size_t> dead_after_move;
    std::optional<TimePs> dead_before_ps;
    // The gaps between its own pieces that step (an arc's chords, a long line's commands): from the last rising
    // edge of one to the first of the next, the same definition as between moves.
    std::size_t inside_gaps = 0;
    TimePs dead_inside_ps = 0;      // their sum
    TimePs dead_inside_max_ps = 0;  // the longest
};

struct TimingResult {
    std::vector<MoveTiming> moves;              // [programmed move]
    std::size_t feed_moves = 0;                 // cutting moves with a feed error
    std::size_t below_feed_moves = 0;           // planner: cutting moves whose commanded speed never reached F
    std::optional<double> feed_error_mean_pct;  // signed mean over cutting moves
    std::optional<double> feed_error_mean_abs_pct;
    std::optional<double> feed_error_max_abs_pct;
    double job_time_s = 0.0;              // t_job_end - t_job_start
    std::optional<double> motion_time_s;  // sum of the per-move motion times
    std::size_t gap_count = 0;            // gaps between consecutive programmed moves that emit steps (dead_gaps())
    std::optional<double> dead_total_ms, dead_mean_ms, dead_max_ms;
    // The gaps between the pieces of one programmed move (MoveTiming::inside_gaps), summed over the job; the
    // totals are 0 on a run whose moves step in one piece each and none without a move that steps.
    std::size_t inside_gap_count = 0;
    std::optional<double> dead_inside_total_ms, dead_inside_mean_ms, dead_inside_max_ms;
    std::optional<double> dead_all_total_ms;  // between + inside: every gap of the job
    std::optional<double> lead_in_ms;         // job start to the first rising STEP edge (any axis)
    std::optional<double> tail_ms;            // last rising STEP edge to the job end
};

// The job figures folded over the programmed moves in order: feed and motion totals, dead-time gaps, then lead-in,
// tail and job time from the first and last rising edge of the run. compute_timing folds all moves at once; the
// streaming metrics fold them as they close and drop them.
class TimingFold {
public:
    // Programmed move `move` (index into the run's programmed moves) with its timing and first and last edge; sets
    // the move's gap (MoveTiming::dead_*).
    void add(std::size_t move, MoveTiming& mt, std::optional<TimePs> t_first_edge_ps,
             std::optional<TimePs> t_last_edge_ps);
    // `first_edge_ps`, `last_edge_ps`: the run's first and last rising edge on any axis (none: no edges).
    [[nodiscard]] TimingResult finish(TimePs t_job_start_ps, TimePs t_job_end_ps, std::optional<TimePs> first_edge_ps,
                                      std::optional<TimePs> last_edge_ps);

private:
    TimingResult m_out;
    double m_feed_sum = 0.0;
    double m_feed_abs_sum = 0.0;
    std::optional<std::size_t> m_previous;  // the last move with edges, and its last edge
    TimePs m_previous_last_edge_ps = 0;
    TimePs m_dead_total_ps = 0;
    TimePs m_dead_inside_ps = 0;
    TimePs m_dead_inside_max_ps = 0;
};

[[nodiscard]] TimingResult compute_timing(const RunInput& in, const EdgeIndex& idx,
                                          const std::vector<ProgrammedMove>& programmed);

}  // namespace cnc::metrics
