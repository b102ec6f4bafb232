// The order the CAM cuts a drawing's entities in: routes, each a chain of entities the tool follows with the laser
// on, joined by rapids (G0). The orderings:
// - selection: the drawing's order, each entity as drawn (seed 000 §3.3 "On User Selection");
// - seed000: seed 000 §3.3 "Path Optimize" (the AutoLISP gc:* functions): an endpoint connection table, the seed of
//   each route the entity with the lexicographically smallest endpoint, chains grown at both ends;
// - seed003: seed 003 §5.1.2's alignment loop (three swap cases, a chain pass, at most 100 revisions), then a G00
//   wherever an entity does not start where the last one ended (§5.1.3);
// - optimized: ours: seed000's chains, their order from nearest neighbour and 2-opt, each chain's direction (and a
//   closed chain's starting vertex) chosen to shorten the rapids; never more rapid length than seed000.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "cam/drawing.hpp"

namespace cnc::cam {

enum class Order { Selection, Seed000, Seed003, Optimized };

struct Step {
    int entity = 0;         // index into Drawing::entities
    bool reversed = false;  // cut from its end to its start (an arc then turns the other way)
};
using Route = std::vector<Step>;

struct OrderOptions {
    // Endpoints this close are the same point (seed 000's JoinTolerance, A.1 *gc-join-tol* = 0.001).
    double join_tolerance_mm = 0.001;
    // seed003's comparisons: none compares the coordinates as the seed's float fields with ==, as its code does;
    // a distance makes them "within this distance" (our fix).
    std::optional<double> seed003_tolerance_mm;
    geom::Vec2 start_mm;  // where the tool is when the job starts: the first rapid's start
};

const std::vector<std::string>& order_names();  // selection, seed000, seed003, optimized
Order parse_order(const std::string& name);     // BadInput("--order", ...) for another name
std::string order_name(Order order);

// The routes of `order`, every entity in exactly one of them.
std::vector<Route> order_routes(const std::vector<Entity>& entities, Order order, const OrderOptions& options);

// The pieces, for the tests.
std::vector<Route> seed000_routes(const std::vector<Entity>& entities, double join_tolerance_mm);
std::vector<Step> seed003_sequence(const std::vector<Entity>& entities, const std::optional<double>& tolerance_mm);
std::vector<Route> optimized_routes(const std::vector<Entity>& entities, double join_tolerance_mm, geom::Vec2 start_mm);

// The path of one step, in the direction it is cut, and where it starts and ends.
geom::Segment step_path(const std::vector<Entity>& entities, Step step);
geom::Vec2 step_start(const std::vector<Entity>& entities, Step step);
geom::Vec2 step_end(const std::vector<Entity>& entities, Step step);
// The rapid length of routes: from `start_mm` to the first route's start, and from each route's end to the next's.
double rapid_length_mm(const std::vector<Entity>& entities, const std::vector<Route>& routes, geom::Vec2 start_mm);

}  // namespace cnc::cam
