#include "metrics/timing/worst_moves.hpp"

#include <algorithm>
#include <cmath>

#include "metrics/metrics.hpp"

namespace cnc::metrics {

void WorstMovesFold::rank(std::vector<RankedMove>& list, const MoveMetrics& move,
                          const std::optional<double>& figure) const {
    if (!figure) return;
    const RankedMove r{m_added, move.index, move.line, *figure};
    // Later moves come last among equal magnitudes: the new one goes after every move at least as bad.
    const auto at = std::upper_bound(list.begin(), list.end(), r, [](const RankedMove& a, const RankedMove& b) {
        return std::fabs(a.value) > std::fabs(b.value);
    });
    if (static_cast<std::size_t>(at - list.begin()) >= m_n) return;
    list.insert(at, r);
    if (list.size() > m_n) list.pop_back();
}

void WorstMovesFold::add(const MoveMetrics& move) {
    rank(m_lists.contour, move, move.path.contour_max_um);
    rank(m_lists.following, move, move.path.following_max_um);
    rank(m_lists.feed, move, move.timing.feed_error_pct);
    ++m_added;
}

WorstMoves worst_moves(const std::vector<MoveMetrics>& moves, std::size_t n) {
    WorstMovesFold fold(n);
    for (const MoveMetrics& m : moves) fold.add(m);
    return fold.lists();
}

}  // namespace cnc::metrics
