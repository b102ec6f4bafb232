#include "metrics/laser.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace cnc::metrics {

namespace {

struct Interval {
    TimePs begin = 0;
    TimePs end = 0;
};

// Laser-on stretches clipped to the job window.
std::vector<Interval> on_intervals(const EdgeLog& laser, TimePs lo, TimePs hi) {
    std::vector<Interval> out;
    bool level = laser.initial;
    TimePs since = lo;
    const auto close = [&](TimePs until) {
        const TimePs b = std::max(since, lo);
        const TimePs e = std::min(until, hi);
        if (e > b) out.push_back({b, e});
    };
    for (const Edge& e : laser.edges) {
        if (e.level == level) continue;
        if (level) close(e.t_ps);
        level = e.level;
        since = e.t_ps;
    }
    if (level) close(hi);
    return out;
}

// Sorted, disjoint inputs; the result is sorted and disjoint.
std::vector<Interval> intersect(const std::vector<Interval>& a, const std::vector<Interval>& b) {
    std::vector<Interval> out;
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < a.size() && j < b.size()) {
        const TimePs lo = std::max(a[i].begin, b[j].begin);
        const TimePs hi = std::min(a[i].end, b[j].end);
        if (hi > lo) out.push_back({lo, hi});
        if (a[i].end < b[j].end) ++i; else ++j;
    }
    return out;
}

void append_merged(std::vector<Interval>& out, Interval iv) {
    if (iv.end <= iv.begin) return;
    if (!out.empty() && out.back().end >= iv.begin) {
        out.back().end = std::max(out.back().end, iv.end);
    } else {
        out.push_back(iv);
    }
}

TimePs total(const std::vector<Interval>& v) {
    TimePs sum = 0;
    for (const Interval& iv : v) sum += iv.end - iv.begin;
    return sum;
}

std::vector<Interval> slow_intervals(const RunInput& in) {
    constexpr TimePs kMin = std::numeric_limits<TimePs>::min();
    constexpr TimePs kMax = std::numeric_limits<TimePs>::max();
    const MoveTimeline timeline(in.moves);
    const std::vector<ToolSample>& tool = in.tool;
    std::vector<Interval> out;
    append_merged(out, {kMin, tool.front().t_ps});
    for (std::size_t j = 0; j + 1 < tool.size(); ++j) {
        const TimePs dt = tool[j + 1].t_ps - tool[j].t_ps;
        if (dt <= 0) continue;
        const double dist_mm = geom::distance(tool[j].pos, tool[j + 1].pos);
        const double speed_mm_per_s = dist_mm / ps_to_s(dt);
        const double feed = in.moves[timeline.active_at(tool[j].t_ps).value_or(0)].feed_mm_per_min;
        const bool slow = dist_mm == 0.0 || speed_mm_per_s < kDwellSpeedFraction * feed / 60.0;
        if (slow) append_merged(out, {tool[j].t_ps, tool[j + 1].t_ps});
    }
    append_merged(out, {tool.back().t_ps, kMax});
    return out;
}

double ms(TimePs t) { return ps_to_s(t) * 1e3; }

}  // namespace

std::optional<LaserResult> compute_laser(const RunInput& in, const EdgeIndex& idx) {
    if (!in.laser) return std::nullopt;
    LaserResult out;
    const std::vector<Interval> on = on_intervals(*in.laser, in.t_job_start_ps, in.t_job_end_ps);
    out.on_ms = ms(total(on));
    if (in.moves.empty()) return out;

    std::vector<Interval> rapid;
    for (std::size_t m = 0; m < in.moves.size(); ++m) {
        if (in.moves[m].rapid && idx.move_first_edge_ps[m]) {
            append_merged(rapid, {*idx.move_first_edge_ps[m], *idx.move_last_edge_ps[m]});
        }
    }
    out.on_in_rapid_ms = ms(total(intersect(on, rapid)));

    if (in.tool.empty()) return out;
    std::vector<Interval> dwell;
    for (const Interval& iv : intersect(on, slow_intervals(in))) append_merged(dwell, iv);
    out.dwell_ms = ms(total(dwell));
    out.dwell_intervals = dwell.size();
    const auto longest = std::max_element(dwell.begin(), dwell.end(), [](const Interval& a, const Interval& b) {
        return a.end - a.begin < b.end - b.begin;
    });
    if (longest != dwell.end()) {
        out.dwell_longest_ms = ms(longest->end - longest->begin);
        out.dwell_longest_at_s = ps_to_s(longest->begin);
    }
    return out;
}

}  // namespace cnc::metrics
