#include "cam/ordering.hpp"

#include "cam/seed003_compare.hpp"
#include "common/bad_input.hpp"

namespace cnc::cam {

namespace {

// A sequence cut into routes wherever a step does not start where the last one ended.
template <typename Same>
std::vector<Route> split_routes(const std::vector<Entity>& entities, const std::vector<Step>& sequence, Same same) {
    std::vector<Route> routes;
    for (const Step& s : sequence) {
        if (routes.empty() || !same(step_end(entities, routes.back().back()), step_start(entities, s))) {
            routes.emplace_back();
        }
        routes.back().push_back(s);
    }
    return routes;
}

}  // namespace

const std::vector<std::string>& order_names() {
    static const std::vector<std::string> names = {"selection", "seed000", "seed003", "optimized"};
    return names;
}

Order parse_order(const std::string& name) {
    const std::vector<std::string>& names = order_names();
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) return static_cast<Order>(i);
    }
    throw BadInput("--order " + name, "not an ordering: selection, seed000, seed003 or optimized (docs/cam.md)");
}

std::string order_name(Order order) {
    return order_names().at(static_cast<std::size_t>(order));
}

geom::Segment step_path(const std::vector<Entity>& entities, Step step) {
    const geom::Segment& s = entities.at(static_cast<std::size_t>(step.entity)).path;
    return step.reversed ? reversed(s) : s;
}

geom::Vec2 step_start(const std::vector<Entity>& entities, Step step) {
    const geom::Segment& s = entities.at(static_cast<std::size_t>(step.entity)).path;
    return step.reversed ? s.end : s.start;
}

geom::Vec2 step_end(const std::vector<Entity>& entities, Step step) {
    const geom::Segment& s = entities.at(static_cast<std::size_t>(step.entity)).path;
    return step.reversed ? s.start : s.end;
}

double rapid_length_mm(const std::vector<Entity>& entities, const std::vector<Route>& routes, geom::Vec2 start_mm) {
    double total = 0.0;
    geom::Vec2 at = start_mm;
    for (const Route& r : routes) {
        total += geom::distance(at, step_start(entities, r.front()));
        at = step_end(entities, r.back());
    }
    return total;
}

std::vector<Route> order_routes(const std::vector<Entity>& entities, Order order, const OrderOptions& options) {
    const double tol = options.join_tolerance_mm;
    switch (order) {
        case Order::Seed000:
            return seed000_routes(entities, tol);
        case Order::Optimized:
            return optimized_routes(entities, tol, options.start_mm);
        case Order::Seed003: {
            const Seed003Same same{options.seed003_tolerance_mm};
            return split_routes(entities, seed003_sequence(entities, options.seed003_tolerance_mm), same);
        }
        case Order::Selection:
            break;
    }
    std::vector<Step> drawn;
    for (std::size_t i = 0; i < entities.size(); ++i) drawn.push_back({static_cast<int>(i), false});
    return split_routes(entities, drawn, [tol](geom::Vec2 a, geom::Vec2 b) { return geom::distance(a, b) <= tol; });
}

}  // namespace cnc::cam
