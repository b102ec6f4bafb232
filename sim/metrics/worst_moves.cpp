#include "metrics/worst_moves.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace cnc::metrics {

namespace {

using Figure = std::optional<double> (*)(const MoveMetrics&);

std::vector<RankedMove> worst(const std::vector<MoveMetrics>& moves, std::size_t n, Figure figure) {
    std::vector<RankedMove> ranked;
    for (std::size_t i = 0; i < moves.size(); ++i) {
        if (const std::optional<double> v = figure(moves[i])) ranked.push_back({i, *v});
    }
    const auto worse = [](const RankedMove& a, const RankedMove& b) {
        const double ma = std::fabs(a.value);
        const double mb = std::fabs(b.value);
        return ma > mb || (ma == mb && a.move < b.move);
    };
    const std::size_t k = std::min(n, ranked.size());
    std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(k), ranked.end(), worse);
    ranked.resize(k);
    return ranked;
}

}  // namespace

WorstMoves worst_moves(const std::vector<MoveMetrics>& moves, std::size_t n) {
    return {worst(moves, n, [](const MoveMetrics& m) { return m.path.contour_max_um; }),
            worst(moves, n, [](const MoveMetrics& m) { return m.path.following_max_um; }),
            worst(moves, n, [](const MoveMetrics& m) { return m.timing.feed_error_pct; })};
}

}  // namespace cnc::metrics
