#include "metrics/laser_exposure.hpp"

#include <algorithm>
#include <cmath>

namespace cnc::metrics {

namespace {

// Laser on-time within [a, b), with `next` the index of the first edge after a (advanced as time goes on).
double on_time_s(const EdgeLog& laser, TimePs a, TimePs b, std::size_t& next) {
    bool level = next == 0 ? laser.initial : laser.edges[next - 1].level;
    while (next < laser.edges.size() && laser.edges[next].t_ps <= a) level = laser.edges[next++].level;
    TimePs on = 0;
    TimePs t = a;
    std::size_t i = next;
    while (i < laser.edges.size() && laser.edges[i].t_ps < b) {
        if (level) on += laser.edges[i].t_ps - t;
        t = laser.edges[i].t_ps;
        level = laser.edges[i].level;
        ++i;
    }
    if (level) on += b - t;
    return ps_to_s(on);
}

}  // namespace

LaserExposure laser_exposure(const std::vector<ToolSample>& tool, const EdgeLog& laser) {
    LaserExposure e;
    double bin_start_mm = 0.0;
    double bin_time_s = 0.0;
    double bin_path_mm = 0.0;
    std::size_t next = 0;
    auto close_bin = [&] {
        if (bin_path_mm > 0.0 && bin_time_s / bin_path_mm > e.peak_s_per_mm) {
            e.peak_s_per_mm = bin_time_s / bin_path_mm;
            e.peak_at_path_mm = bin_start_mm;
        }
    };
    for (std::size_t i = 1; i < tool.size(); ++i) {
        const double on = on_time_s(laser, tool[i - 1].t_ps, tool[i].t_ps, next);
        if (on <= 0.0) continue;
        const double d = std::hypot(tool[i].pos.x_mm - tool[i - 1].pos.x_mm, tool[i].pos.y_mm - tool[i - 1].pos.y_mm);
        e.on_time_s += on;
        e.lasered_path_mm += d;
        bin_time_s += on;
        bin_path_mm += d;
        if (bin_path_mm >= kExposureBinMm) {
            close_bin();
            bin_start_mm = e.lasered_path_mm;
            bin_time_s = 0.0;
            bin_path_mm = 0.0;
        }
    }
    if (bin_path_mm >= 0.5 * kExposureBinMm) close_bin();  // a short last bin would read as a dwell
    e.mean_s_per_mm = e.lasered_path_mm > 0.0 ? e.on_time_s / e.lasered_path_mm : 0.0;
    return e;
}

}  // namespace cnc::metrics
