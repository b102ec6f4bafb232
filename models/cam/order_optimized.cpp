// Our ordering: seed 000's chains (one laser cycle each), ordered to shorten the rapids. Two starting tours, the
// chains in seed000's order and a nearest-neighbour tour from the tool's start, each improved by 2-opt (which also
// turns single chains round) and by moving each closed chain's start to its best vertex; the shorter one wins, so
// the rapids are never longer than seed000's.
#include <algorithm>
#include <limits>
#include <tuple>

#include "cam/ordering.hpp"

namespace cnc::cam {

namespace {

constexpr double kGainMm = 1e-9;  // an improvement smaller than this is rounding, not a shorter tour
constexpr int kMaxPasses = 200;   // improvement passes; each shortens the tour, so this only bounds a long drawing

class Tour {
public:
    Tour(const std::vector<Entity>& entities, double tol, geom::Vec2 start)
        : m_entities(entities), m_tol(tol), m_start(start) {}

    geom::Vec2 entry(const Route& r) const { return step_start(m_entities, r.front()); }
    geom::Vec2 exit(const Route& r) const { return step_end(m_entities, r.back()); }
    bool closed(const Route& r) const { return geom::distance(entry(r), exit(r)) <= m_tol; }

    static void turn(Route& r) {
        std::reverse(r.begin(), r.end());
        for (Step& s : r) s.reversed = !s.reversed;
    }

    // The chains in nearest-neighbour order: from where the tool is, the nearest entry of any chain left (either
    // end of an open chain, any vertex of a closed one).
    std::vector<Route> nearest_neighbour(std::vector<Route> chains) const {
        std::vector<Route> tour;
        geom::Vec2 at = m_start;
        while (!chains.empty()) {
            double best = std::numeric_limits<double>::infinity();
            std::size_t best_chain = 0, best_vertex = 0;
            bool best_turned = false;
            for (std::size_t c = 0; c < chains.size(); ++c) {
                const Route& r = chains[c];
                if (closed(r)) {
                    for (std::size_t v = 0; v < r.size(); ++v) {
                        const double d = geom::distance(at, step_start(m_entities, r[v]));
                        if (d < best) std::tie(best, best_chain, best_vertex, best_turned) = std::tuple(d, c, v, false);
                    }
                } else {
                    const double forward = geom::distance(at, entry(r)), backward = geom::distance(at, exit(r));
                    const double d = std::min(forward, backward);
                    if (d < best)
                        std::tie(best, best_chain, best_vertex, best_turned) = std::tuple(d, c, 0, backward < forward);
                }
            }
            Route r = std::move(chains[best_chain]);
            chains.erase(chains.begin() + static_cast<std::ptrdiff_t>(best_chain));
            std::rotate(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(best_vertex), r.end());
            if (best_turned) turn(r);
            at = exit(r);
            tour.push_back(std::move(r));
        }
        return tour;
    }

    void improve(std::vector<Route>& tour) const {
        for (int pass = 0; pass < kMaxPasses; ++pass) {
            const bool a = two_opt(tour);
            const bool b = best_vertices(tour);
            if (!a && !b) return;
        }
    }

private:
    geom::Vec2 exit_before(const std::vector<Route>& tour, std::size_t i) const {
        return i == 0 ? m_start : exit(tour[i - 1]);
    }

    // Reversing chains i..j (and turning each) changes only the rapids into i and out of j.
    bool two_opt(std::vector<Route>& tour) const {
        bool improved = false;
        const std::size_t m = tour.size();
        for (std::size_t i = 0; i < m; ++i) {
            for (std::size_t j = i; j < m; ++j) {
                const geom::Vec2 before = exit_before(tour, i);
                double old_cost = geom::distance(before, entry(tour[i]));
                double new_cost = geom::distance(before, exit(tour[j]));
                if (j + 1 < m) {
                    const geom::Vec2 after = entry(tour[j + 1]);
                    old_cost += geom::distance(exit(tour[j]), after);
                    new_cost += geom::distance(entry(tour[i]), after);
                }
                if (new_cost < old_cost - kGainMm) {
                    std::reverse(tour.begin() + static_cast<std::ptrdiff_t>(i),
                                 tour.begin() + static_cast<std::ptrdiff_t>(j) + 1);
                    for (std::size_t k = i; k <= j; ++k) turn(tour[k]);
                    improved = true;
                }
            }
        }
        return improved;
    }

    // A closed chain is entered and left at the same vertex: the one nearest the rapids on both sides.
    bool best_vertices(std::vector<Route>& tour) const {
        bool improved = false;
        for (std::size_t k = 0; k < tour.size(); ++k) {
            Route& r = tour[k];
            if (!closed(r)) continue;
            const geom::Vec2 before = exit_before(tour, k);
            const auto cost = [&](geom::Vec2 v) {
                return geom::distance(before, v) + (k + 1 < tour.size() ? geom::distance(v, entry(tour[k + 1])) : 0.0);
            };
            double best = cost(entry(r));
            std::size_t best_vertex = 0;
            for (std::size_t v = 1; v < r.size(); ++v) {
                const double c = cost(step_start(m_entities, r[v]));
                if (c < best - kGainMm) {
                    best = c;
                    best_vertex = v;
                }
            }
            if (best_vertex != 0) {
                std::rotate(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(best_vertex), r.end());
                improved = true;
            }
        }
        return improved;
    }

    const std::vector<Entity>& m_entities;
    double m_tol;
    geom::Vec2 m_start;
};

}  // namespace

std::vector<Route> optimized_routes(const std::vector<Entity>& entities, double join_tolerance_mm,
                                    geom::Vec2 start_mm) {
    const Tour tour(entities, join_tolerance_mm, start_mm);
    std::vector<Route> from_seed = seed000_routes(entities, join_tolerance_mm);
    std::vector<Route> from_nearest = tour.nearest_neighbour(from_seed);
    tour.improve(from_seed);
    tour.improve(from_nearest);
    return rapid_length_mm(entities, from_nearest, start_mm) < rapid_length_mm(entities, from_seed, start_mm)
               ? from_nearest
               : from_seed;
}

}  // namespace cnc::cam
