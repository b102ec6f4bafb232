// The programmed moves (G-code lines) of a run as groups of the executed pieces that carried them out (an arc's
// chords, a long line's commands, or one planner move): the unit that feed error, motion time and dead time are
// defined on, whatever the CAM, the PC program or the planner cut the move into.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "metrics/pulse/edge_index.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

struct ProgrammedMove {
    std::size_t first_piece = 0;  // [first_piece, end_piece) of RunInput::moves
    std::size_t end_piece = 0;
    std::vector<EdgeRange> edges;  // [axis] the rising edges of its pieces (consecutive pieces: one range)
    std::optional<TimePs> t_first_edge_ps, t_last_edge_ps;  // any axis
};

// True if pieces a and b execute the same programmed move.
[[nodiscard]] bool same_programmed_move(const MoveSpec& a, const MoveSpec& b);

// Consecutive pieces with the same MoveSpec::programmed (>= 0) form one programmed move; a piece with -1 is one.
[[nodiscard]] std::vector<ProgrammedMove> programmed_moves(const RunInput& in, const EdgeIndex& idx);

}  // namespace cnc::metrics
