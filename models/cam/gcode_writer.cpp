#include "cam/gcode_writer.hpp"

#include <cmath>

#include <fmt/format.h>

namespace cnc::cam {

namespace {

// Three decimals (seed 000 §3.1), without a "-0.000".
std::string number(double v) {
    std::string text = fmt::format(FMT_STRING("{:.3f}"), v);
    if (text == "-0.000") text = "0.000";
    return text;
}

std::string xy(geom::Vec2 p) {
    return "X" + number(p.x_mm) + " Y" + number(p.y_mm);
}

}  // namespace

std::string write_gcode(const std::vector<Entity>& entities, const std::vector<Route>& routes,
                        const GcodeOptions& options) {
    std::string out = "G21\nG90\nG17\nG94\n";
    for (const Route& route : routes) {
        out += "G0 " + xy(step_start(entities, route.front())) + "\n";
        out += "M3 S" + fmt::format(FMT_STRING("{:g}"), options.laser_power) + "\n";
        for (const Step& step : route) {
            const Entity& e = entities.at(static_cast<std::size_t>(step.entity));
            const geom::Segment s = step_path(entities, step);
            const double per_min = e.cut() ? options.cut_feed_mm_per_min : options.engrave_feed_mm_per_min;
            const double feed = options.feed_in_mm_per_s ? per_min / 60.0 : per_min;
            const std::string f = " F" + fmt::format(FMT_STRING("{:g}"), feed) + "\n";
            if (!s.is_arc) {
                out += "G1 " + xy(s.end) + f;
                continue;
            }
            const geom::Vec2 ij = s.center - s.start;
            out +=
                (s.sweep_rad > 0.0 ? "G3 " : "G2 ") + xy(s.end) + " I" + number(ij.x_mm) + " J" + number(ij.y_mm) + f;
        }
        out += "M5\n";
    }
    out += "M30\n";
    return out;
}

}  // namespace cnc::cam
