// The routes as G-code (seed 000 §2.2's program form): G21 G90 G17 G94, a G0 to each route's start, the laser on
// (M3 S) for the route and off (M5) after it, G1/G2/G3 with I/J (centre minus start) at the entity's feed, three
// decimals, M30.
#pragma once
#include <string>
#include <vector>

#include "cam/ordering.hpp"

namespace cnc::cam {

struct GcodeOptions {
    // seed 000 §3.3's form: "Feed Rate" for every colour but red, "Cut Feed Rate" for red. 800 mm/min is seed 000
    // §2.2's sample program's; the seed gives no cut feed: ours is a quarter of it, red being the slow through-cut.
    double engrave_feed_mm_per_min = 800.0;
    double cut_feed_mm_per_min = 200.0;
    // The S word with M3 (seed 000 §2.2's sample: M3 S255). Architectures that switch the laser by motion kind
    // ignore it; those that follow the job's M3/S need it above 0.
    double laser_power = 255.0;
    // The unit the F words are written in: mm/min (G94), or mm/s for a machine that reads F so (seed 003 §5.1.3:
    // "F100 = 100 mm/sec"; the scenario's host.feed_unit). The feeds above stay in mm/min.
    bool feed_in_mm_per_s = false;
};

std::string write_gcode(const std::vector<Entity>& entities, const std::vector<Route>& routes,
                        const GcodeOptions& options);

}  // namespace cnc::cam
