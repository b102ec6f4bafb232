#include "common/edge_log.hpp"

#include <algorithm>

namespace cnc {

bool EdgeLog::level_at(TimePs t_ps) const {
    const auto it =
        std::upper_bound(edges.begin(), edges.end(), t_ps, [](TimePs t, const Edge& e) { return t < e.t_ps; });
    return it == edges.begin() ? initial : std::prev(it)->level;
}

// Calls f(t) for every edge that changes the level to `level`.
template <typename F>
static void each_edge_to(const std::vector<Edge>& edges, bool initial, bool level, F f) {
    bool prev = initial;
    for (const Edge& e : edges) {
        if (e.level == level && prev != level) f(e.t_ps);
        prev = e.level;
    }
}

static std::size_t count_to(const std::vector<Edge>& edges, bool initial, bool level) {
    std::size_t n = 0;
    each_edge_to(edges, initial, level, [&n](TimePs) { ++n; });
    return n;
}

// Counted first so that the times take exactly their size: a long job's STEP rises are its largest array.
static std::vector<TimePs> edges_to(const std::vector<Edge>& edges, bool initial, bool level) {
    std::vector<TimePs> out;
    out.reserve(count_to(edges, initial, level));
    each_edge_to(edges, initial, level, [&out](TimePs t) { out.push_back(t); });
    return out;
}

std::vector<TimePs> EdgeLog::rising() const {
    return edges_to(edges, initial, true);
}
std::vector<TimePs> EdgeLog::falling() const {
    return edges_to(edges, initial, false);
}
std::size_t EdgeLog::count_falling() const {
    return count_to(edges, initial, false);
}

EdgeLog EdgeLog::take_before(TimePs t_ps) {
    const auto end =
        std::lower_bound(edges.begin(), edges.end(), t_ps, [](const Edge& e, TimePs t) { return e.t_ps < t; });
    EdgeLog out{name, initial, {edges.begin(), end}};
    if (!out.edges.empty()) initial = out.edges.back().level;
    edges.erase(edges.begin(), end);
    return out;
}

}  // namespace cnc
