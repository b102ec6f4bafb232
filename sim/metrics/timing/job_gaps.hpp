// Every dead-time gap of a run, between the programmed moves and inside them (between the pieces of one move: an
// arc's chords, a long line's commands), in job order: the detailed report's list of the gaps inside moves and
// the dead-time plot (docs/metrics.md "Job timing").
#pragma once
#include <cstddef>
#include <vector>

#include "metrics/move_metrics.hpp"
#include "metrics/timing/move_records.hpp"

namespace cnc::metrics {

struct JobGap {
    std::size_t after_move = 0;  // index into the programmed moves; == before_move for a gap inside a move
    std::size_t before_move = 0;
    std::size_t after_piece = 0;  // index into the executed pieces: the last that stepped before the gap
    std::size_t before_piece = 0;
    TimePs dead_ps = 0;  // first rising edge of before_piece - last rising edge of after_piece (any axis)
    [[nodiscard]] bool inside() const { return after_move == before_move; }
};

// From one piece that steps to the next, in order; the pieces are the programmed moves' (MoveMetrics::pieces of
// each, in order), which a streamed run keeps only with the detailed report: without them (or with a list that
// does not match the moves) there is no list.
[[nodiscard]] std::vector<JobGap> job_gaps(const MoveRecords& moves, const std::vector<MoveMetrics>& pieces);

}  // namespace cnc::metrics
