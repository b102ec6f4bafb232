// What an ordering gives a drawing: the figures `cncsim cam` reports and --compare-orders sets side by side.
#pragma once
#include <vector>

#include "cam/ordering.hpp"

namespace cnc::cam {

struct RouteStats {
    int routes = 0;       // rapids (a G0 to each route's start) and laser on/off cycles (M3 ... M5)
    int moves = 0;        // cutting moves: G1, G2, G3 (one per line or arc; a polyline has one per segment)
    double rapid_mm = 0;  // from the tool's start to the first route, and between routes
    double cut_mm = 0;    // along the lines and arcs
    [[nodiscard]] int commands() const { return routes + moves; }  // motion commands: G0 and G1/G2/G3
};

RouteStats route_stats(const std::vector<Entity>& entities, const std::vector<Route>& routes, geom::Vec2 start_mm);

}  // namespace cnc::cam
