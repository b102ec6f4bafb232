#include "metrics/laser/laser_exposure.hpp"

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

void LaserExposureFold::close_bin(LaserExposure& e) const {
    if (m_bin_path_mm > 0.0 && m_bin_time_s / m_bin_path_mm > e.peak_s_per_mm) {
        e.peak_s_per_mm = m_bin_time_s / m_bin_path_mm;
        e.peak_at_path_mm = m_bin_start_mm;
    }
}

void LaserExposureFold::fold(Samples begin, Samples end, const EdgeLog& laser) {
    std::size_t next = 0;
    for (Samples s = begin; s != end; ++s) {
        const std::optional<ToolSample> prev = m_last;
        m_last = *s;
        if (!prev) continue;
        const double on = on_time_s(laser, prev->t_ps, s->t_ps, next);
        if (on <= 0.0) continue;
        const double d = std::hypot(s->pos.x_mm - prev->pos.x_mm, s->pos.y_mm - prev->pos.y_mm);
        m_e.on_time_s += on;
        m_e.lasered_path_mm += d;
        m_bin_time_s += on;
        m_bin_path_mm += d;
        if (m_bin_path_mm >= kExposureBinMm) {
            close_bin(m_e);
            m_bin_start_mm = m_e.lasered_path_mm;
            m_bin_time_s = 0.0;
            m_bin_path_mm = 0.0;
        }
    }
}

LaserExposure LaserExposureFold::finish() const {
    LaserExposure e = m_e;
    if (m_bin_path_mm >= 0.5 * kExposureBinMm) close_bin(e);  // a short last bin would read as a dwell
    e.mean_s_per_mm = e.lasered_path_mm > 0.0 ? e.on_time_s / e.lasered_path_mm : 0.0;
    return e;
}

LaserExposure laser_exposure(const std::vector<ToolSample>& tool, const EdgeLog& laser) {
    LaserExposureFold fold;
    fold.fold(tool.begin(), tool.end(), laser);
    return fold.finish();
}

}  // namespace cnc::metrics
