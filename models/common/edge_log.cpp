#include "common/edge_log.hpp"

#include <algorithm>

namespace cnc {

bool EdgeLog::level_at(TimePs t_ps) const {
    const auto it = std::upper_bound(edges.begin(), edges.end(), t_ps,
                                     [](TimePs t, const Edge& e) { return t < e.t_ps; });
    return it == edges.begin() ? initial : std::prev(it)->level;
}

static std::vector<TimePs> edges_to(const std::vector<Edge>& edges, bool initial, bool level) {
    std::vector<TimePs> out;
    bool prev = initial;
    for (const Edge& e : edges) {
        if (e.level == level && prev != level) out.push_back(e.t_ps);
        prev = e.level;
    }
    return out;
}

std::vector<TimePs> EdgeLog::rising() const { return edges_to(edges, initial, true); }
std::vector<TimePs> EdgeLog::falling() const { return edges_to(edges, initial, false); }

}  // namespace cnc
