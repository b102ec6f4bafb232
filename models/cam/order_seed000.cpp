// seed 000 §3.3 "Path Optimize" (A.1, the gc:* functions): the endpoint connection table and the chains.
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <utility>

#include "cam/ordering.hpp"

namespace cnc::cam {

namespace {

constexpr double kTieMm = 1e-12;  // A.1's tie tolerance of the lexicographic point comparison

// The table's key (A.1 point-id: "round(x/tol),round(y/tol)"): endpoints that round to the same cell meet.
using PointId = std::pair<long long, long long>;
PointId point_id(geom::Vec2 p, double tol) {
    return {std::llround(p.x_mm / tol), std::llround(p.y_mm / tol)};
}

// x first, then y, each equal within kTieMm.
bool lexicographically_less(geom::Vec2 a, geom::Vec2 b) {
    if (a.x_mm < b.x_mm - kTieMm) return true;
    if (std::fabs(a.x_mm - b.x_mm) > kTieMm) return false;
    return a.y_mm < b.y_mm - kTieMm;
}

class Chainer {
public:
    Chainer(const std::vector<Entity>& entities, double tol)
        : m_entities(entities), m_tol(tol), m_visited(entities.size(), false) {
        for (std::size_t i = 0; i < entities.size(); ++i) {  // each index consed to the front: newest first
            for (const geom::Vec2 p : {entities[i].path.start, entities[i].path.end}) {
                std::deque<int>& at = m_table[point_id(p, tol)];
                at.push_front(static_cast<int>(i));
            }
        }
    }

    std::vector<Route> routes() {
        std::vector<Route> out;
        for (int seed = next_seed(); seed >= 0; seed = next_seed()) out.push_back(chain_from(seed));
        return out;
    }

private:
    // The unvisited entity whose smaller endpoint is the smallest (the first in drawing order on a tie); -1: none.
    int next_seed() const {
        int best = -1;
        geom::Vec2 best_point;
        for (std::size_t i = 0; i < m_entities.size(); ++i) {
            if (m_visited[i]) continue;
            const geom::Vec2 p = smaller_end(m_entities[i].path);
            if (best < 0 || lexicographically_less(p, best_point)) {
                best = static_cast<int>(i);
                best_point = p;
            }
        }
        return best;
    }

    // The end point is the smaller unless the start is strictly smaller (a circle's equal ends: its end).
    static geom::Vec2 smaller_end(const geom::Segment& s) {
        return lexicographically_less(s.start, s.end) ? s.start : s.end;
    }

    Route chain_from(int seed) {
        const geom::Segment& s = m_entities[static_cast<std::size_t>(seed)].path;
        std::deque<Step> chain{{seed, !lexicographically_less(s.start, s.end)}};
        m_visited[static_cast<std::size_t>(seed)] = true;
        // One entity at the end, then one at the start, until neither grows: the order that makes seed 000's
        // worked example start its main contour at (250,100).
        for (bool grew = true; grew;) {
            grew = false;
            if (const auto next = connect(step_end(m_entities, chain.back()), false)) {
                chain.push_back(*next);
                grew = true;
            }
            if (const auto prev = connect(step_start(m_entities, chain.front()), true)) {
                chain.push_front(*prev);
                grew = true;
            }
        }
        return Route(chain.begin(), chain.end());
    }

    // The newest unvisited entity of p's table entry that meets p (gc:pt=, distance <= tol), oriented to leave p
    // (`into`: to arrive at p).
    std::optional<Step> connect(geom::Vec2 p, bool into) {
        const auto it = m_table.find(point_id(p, m_tol));
        if (it == m_table.end()) return std::nullopt;
        for (const int i : it->second) {
            const std::size_t u = static_cast<std::size_t>(i);
            if (m_visited[u]) continue;
            const geom::Segment& s = m_entities[u].path;
            const geom::Vec2 near = into ? s.end : s.start;
            const geom::Vec2 far = into ? s.start : s.end;
            bool reversed = false;
            if (geom::distance(near, p) <= m_tol) {
                reversed = false;
            } else if (geom::distance(far, p) <= m_tol) {
                reversed = true;
            } else {
                continue;
            }
            m_visited[u] = true;
            return Step{i, reversed};
        }
        return std::nullopt;
    }

    const std::vector<Entity>& m_entities;
    double m_tol;
    std::vector<bool> m_visited;
    std::map<PointId, std::deque<int>> m_table;
};

}  // namespace

std::vector<Route> seed000_routes(const std::vector<Entity>& entities, double join_tolerance_mm) {
    return Chainer(entities, join_tolerance_mm).routes();
}

}  // namespace cnc::cam
