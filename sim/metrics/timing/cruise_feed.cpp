#include "metrics/timing/cruise_feed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "metrics/commanded.hpp"

namespace cnc::metrics {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The angle from a to b about the centre, in (-pi, pi]: consecutive edge positions are far less than half a turn
// apart, so summing these follows the tool round a full circle.
double turn_rad(geom::Vec2 c, geom::Vec2 a, geom::Vec2 b) {
    double d = std::atan2(b.y_mm - c.y_mm, b.x_mm - c.x_mm) - std::atan2(a.y_mm - c.y_mm, a.x_mm - c.x_mm);
    if (d > kPi) d -= 2.0 * kPi;
    if (d <= -kPi) d += 2.0 * kPi;
    return d;
}

}  // namespace

std::optional<std::pair<TimePs, TimePs>> cruise_window(const CommandedTrajectory& c, TimePs t_begin_ps, TimePs t_end_ps,
                                                       double speed_mm_per_s) {
    std::optional<std::pair<TimePs, TimePs>> out;
    const double at_speed = (1.0 - kCruiseTolerance) * speed_mm_per_s;
    const TimePs step = std::max<TimePs>(c.scan_step_ps, 1);
    for (TimePs t = t_begin_ps;; t = std::min(t + step, t_end_ps)) {
        if (geom::norm(commanded_at(c, t).vel_mm_per_s) >= at_speed) {
            if (!out) out = std::make_pair(t, t);
            out->second = t;
        }
        if (t >= t_end_ps) break;
    }
    return out;
}

StepPosition::StepPosition(const RunInput& in, const EdgeIndex& idx)
    : m_in(in), m_idx(idx), m_next(idx.axes.size(), 0), m_count(idx.axes.size(), 0) {
    // A window of a streamed run starts from the counts before it.
    if (!in.commanded) return;
    const std::vector<std::int64_t>& before = in.commanded->count_before_steps;
    for (std::size_t a = 0; a < m_count.size() && a < before.size(); ++a) m_count[a] = before[a];
}

void StepPosition::advance_before(TimePs t_ps) {
    for (std::size_t a = 0; a < m_idx.axes.size(); ++a) {
        const AxisEdges& e = m_idx.axes[a];
        while (m_next[a] < e.rising.size() && e.rising[m_next[a]] < t_ps) m_count[a] += e.rising_sign[m_next[a]++];
    }
}

geom::Vec2 StepPosition::position() const {
    const geom::Vec2 origin = m_in.commanded ? m_in.commanded->origin_mm : geom::Vec2{};
    double mm[kPathAxes] = {0.0, 0.0};
    for (std::size_t a = 0; a < kPathAxes && a < m_count.size(); ++a) {
        mm[a] = static_cast<double>(m_count[a]) / m_in.axes[a].steps_per_mm;
    }
    return origin + geom::Vec2{mm[0], mm[1]};
}

std::optional<StepPosition::Travel> StepPosition::travel(const geom::Segment& path, TimePs t_from_ps, TimePs t_to_ps) {
    advance_before(t_from_ps);
    const geom::Vec2 dir =
        path.is_arc || path.length_mm() <= 0.0 ? geom::Vec2{} : (path.end - path.start) * (1.0 / path.length_mm());
    const double turn_sign = path.sweep_rad < 0.0 ? -1.0 : 1.0;
    std::optional<Travel> out;
    geom::Vec2 first{};
    geom::Vec2 last{};
    double turned_rad = 0.0;
    for (;;) {
        // The next instant with a rising edge on any axis, and every edge at it.
        TimePs t = std::numeric_limits<TimePs>::max();
        for (std::size_t a = 0; a < m_idx.axes.size(); ++a) {
            if (m_next[a] < m_idx.axes[a].rising.size()) t = std::min(t, m_idx.axes[a].rising[m_next[a]]);
        }
        if (t > t_to_ps) break;
        advance_before(t + 1);
        const geom::Vec2 p = position();
        if (!out) {
            out = Travel{0.0, t, t};
            first = p;
        } else if (path.is_arc) {
            turned_rad += turn_rad(path.center, last, p);
        }
        out->t_last_ps = t;
        last = p;
    }
    if (!out || out->t_last_ps == out->t_first_ps) return std::nullopt;
    out->path_mm = path.is_arc ? turned_rad * turn_sign * path.radius_mm() : geom::dot(last - first, dir);
    return out;
}

}  // namespace cnc::metrics
