// The moves that did worst on each per-move figure, so that the summary of a long job says where to look (by move
// index and G-code line). Moves without the figure (no tool samples, no feed measured) are left out.
#pragma once
#include <cstddef>
#include <vector>

#include "metrics/metrics.hpp"

namespace cnc::metrics {

inline constexpr std::size_t kWorstMovesListed = 5;

struct RankedMove {
    std::size_t move = 0;  // index into RunMetrics::moves
    double value = 0.0;    // the figure, signed as the move has it
};

// Each list worst first by the figure's magnitude; equal magnitudes in move order.
struct WorstMoves {
    std::vector<RankedMove> contour;    // contour_max_um
    std::vector<RankedMove> following;  // following_max_um
    std::vector<RankedMove> feed;       // feed_error_pct
};

[[nodiscard]] WorstMoves worst_moves(const std::vector<MoveMetrics>& moves, std::size_t n = kWorstMovesListed);

}  // namespace cnc::metrics
