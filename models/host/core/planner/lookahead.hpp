// Look-ahead over the planned pieces (seed 004 §3.2: the planner's virtual position runs ahead of the machine):
// the speed at every piece boundary, such that the machine can always stop at the end of what it has seen.
#pragma once
#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

#include "host/core/planner/path_limits.hpp"
#include "host/core/planner/planner_config.hpp"

namespace cnc::host::planner {

struct LookaheadPiece {
    double length_mm;
    PathLimits limits;
    double entry_cap_mm_per_s;  // at its start: min of both pieces' speed limits, or 0 at a stop
    // Last programmed move the planner must have read to build this piece (non-decreasing along the path).
    int last_move_needed;
};

// Speeds at the n+1 boundaries of n pieces, 0 at both ends. While piece k is followed the planner knows the
// pieces needing at most `lookahead_moves` programmed moves counted from piece k's own, and must be able to
// stop at the end of that window: the backward pass over the window (O(window) per piece) gives the highest
// exit speed of piece k that allows it; the forward pass then takes the lower of that and what the
// acceleration limit reaches from the entry speed. A piece's own profile never needs more than its window
// either: from its peak it can still brake to its exit speed, and from there stop within the window.
std::vector<double> boundary_speeds(const std::vector<LookaheadPiece>& pieces, Profile shape, int lookahead_moves);

// The same pass over pieces handed over one at a time: a piece's exit speed is final as soon as the piece past its
// window has been added (or the path has ended), and it equals boundary_speeds' (the same operations in the same
// order). Only the pieces from the first without a final exit speed to the last added are held.
class Lookahead {
public:
    Lookahead(Profile shape, int lookahead_moves) : m_shape(shape), m_lookahead_moves(lookahead_moves) {}
    void add(const LookaheadPiece& piece) { m_pieces.push_back(piece); }
    // The exit speed of the next piece whose exit speed is not taken yet, once final; every one once `ended`.
    [[nodiscard]] std::optional<double> next_exit(bool ended);

private:
    Profile m_shape;
    int m_lookahead_moves;
    std::deque<LookaheadPiece> m_pieces;  // from the next piece on
    std::size_t m_window_end = 0;         // one past the window's last piece, counted from m_pieces' front
    double m_entry_mm_per_s = 0.0;        // the next piece's (the path starts at rest)
};

}  // namespace cnc::host::planner
