#include "metrics/commanded.hpp"

#include <algorithm>
#include <cmath>

namespace cnc::metrics {

namespace {

double axis_of(geom::Vec2 v, std::size_t axis) {
    return axis == 0 ? v.x_mm : v.y_mm;
}

struct AxisFn {
    const CommandedTrajectory& c;
    std::size_t axis;
    double steps_per_mm;
    double origin;
    [[nodiscard]] double pos(const CommandedState& s) const {
        return (axis_of(s.pos_mm, axis) - origin) * steps_per_mm;
    }
    [[nodiscard]] double vel(const CommandedState& s) const { return axis_of(s.vel_mm_per_s, axis) * steps_per_mm; }
};

// Last time in (lo, hi] at which the velocity still has the sign it has at lo (bisection to 1 ps).
TimePs turning_point(const AxisFn& f, TimePs lo, TimePs hi, double v_lo) {
    while (hi - lo > 1) {
        const TimePs mid = lo + (hi - lo) / 2;
        const double v = f.vel(commanded_at(f.c, mid));
        if (v * v_lo > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return hi;
}

// The first ps in (lo, hi] at which the monotone position is at or past `level` (c_lo before it, c_hi at or past
// it), to 1 ps: Newton steps from the linear guess while they stay inside the bracket, bisection otherwise; once
// Newton's root lies within half a ps of its last point that point (or the next ps) is the answer.
TimePs crossing(const AxisFn& f, TimePs lo, TimePs hi, double c_lo, double c_hi, double level) {
    const bool rising = c_hi > c_lo;
    const auto past = [&](double c) { return rising ? c >= level : c <= level; };
    double guess = static_cast<double>(lo) + (level - c_lo) / (c_hi - c_lo) * static_cast<double>(hi - lo);
    for (int i = 0; i < 200 && hi - lo > 1; ++i) {
        TimePs t = static_cast<TimePs>(std::llround(guess));
        if (t <= lo || t >= hi) t = lo + (hi - lo) / 2;
        const CommandedState s = commanded_at(f.c, t);
        const double c = f.pos(s);
        const bool is_past = past(c);
        if (is_past) {
            hi = t;
        } else {
            lo = t;
        }
        const double v = f.vel(s);
        guess = v != 0.0 ? static_cast<double>(t) - (c - level) / v * static_cast<double>(kPsPerSec)
                         : static_cast<double>(lo + (hi - lo) / 2);
        // Newton's root is within half a ps of t: the first ps at or past it is t or the next one.
        if (std::llround(guess) == t) return is_past ? t : t + 1;
    }
    return hi;
}

// The first level is found with exact comparisons: c_lo + 0.5 rounds (0.49999999999999994 + 0.5 is 1.0), and a
// first n taken from that sum skipped the level just above c_lo. n +- 0.5 is exact for any step count.
void add_crossings(const AxisFn& f, TimePs lo, TimePs hi, double c_lo, double c_hi, StepCrossings& out) {
    if (c_hi > c_lo) {
        // levels n - 1/2 in (c_lo, c_hi]
        auto n = static_cast<std::int64_t>(std::floor(c_lo - 0.5));
        while (static_cast<double>(n) - 0.5 <= c_lo) ++n;
        for (; static_cast<double>(n) - 0.5 <= c_hi; ++n) {
            out.up[n].push_back(crossing(f, lo, hi, c_lo, c_hi, static_cast<double>(n) - 0.5));
        }
    } else if (c_hi < c_lo) {
        // levels n + 1/2 in [c_hi, c_lo)
        auto n = static_cast<std::int64_t>(std::ceil(c_lo + 0.5));
        while (static_cast<double>(n) + 0.5 >= c_lo) --n;
        for (; static_cast<double>(n) + 0.5 >= c_hi; --n) {
            out.down[n].push_back(crossing(f, lo, hi, c_lo, c_hi, static_cast<double>(n) + 0.5));
        }
    }
}

}  // namespace

CommandedState commanded_at(const CommandedTrajectory& c, TimePs t_ps) {
    return c.state_at(std::clamp(t_ps, c.t_begin_ps, c.t_end_ps));
}

std::optional<TimePs> StepCrossings::nearest(std::int64_t count, int sign, TimePs t_ps) const {
    const auto& lists = sign > 0 ? up : down;
    const auto it = lists.find(count);
    if (it == lists.end() || it->second.empty()) return std::nullopt;
    const std::vector<TimePs>& times = it->second;
    const auto after = std::lower_bound(times.begin(), times.end(), t_ps);
    if (after == times.begin()) return *after;
    if (after == times.end()) return times.back();
    const TimePs before = *std::prev(after);
    return t_ps - before <= *after - t_ps ? before : *after;
}

StepCrossings step_crossings(const CommandedTrajectory& c, std::size_t axis, double steps_per_mm, TimePs from_ps,
                             TimePs to_ps) {
    StepCrossings out;
    const AxisFn f{c, axis, steps_per_mm, axis_of(c.origin_mm, axis)};
    const TimePs step = std::max<TimePs>(c.scan_step_ps, 1);
    TimePs t0 = c.t_begin_ps;
    if (from_ps > t0) t0 += (from_ps - t0 - 1) / step * step;  // a crossing at from_ps ends the interval before
    const TimePs t_stop = std::min(c.t_end_ps, to_ps);
    CommandedState s0 = commanded_at(c, t0);
    while (t0 < c.t_end_ps && t0 <= t_stop) {
        const TimePs t1 = std::min(t0 + step, c.t_end_ps);
        const CommandedState s1 = commanded_at(c, t1);
        const double v0 = f.vel(s0);
        if (v0 * f.vel(s1) < 0.0) {
            const TimePs tm = turning_point(f, t0, t1, v0);
            const double cm = f.pos(commanded_at(c, tm));
            add_crossings(f, t0, tm, f.pos(s0), cm, out);
            add_crossings(f, tm, t1, cm, f.pos(s1), out);
        } else {
            add_crossings(f, t0, t1, f.pos(s0), f.pos(s1), out);
        }
        t0 = t1;
        s0 = s1;
    }
    for (auto* lists : {&out.up, &out.down}) {
        for (auto& [n, times] : *lists) std::sort(times.begin(), times.end());
    }
    return out;
}

}  // namespace cnc::metrics
