#include "metrics/laser/laser.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace cnc::metrics {

namespace {

// Laser-on stretches clipped to the job window.
std::vector<TimeInterval> on_intervals(const EdgeLog& laser, TimePs lo, TimePs hi) {
    std::vector<TimeInterval> out;
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
std::vector<TimeInterval> intersect(const std::vector<TimeInterval>& a, const std::vector<TimeInterval>& b) {
    std::vector<TimeInterval> out;
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < a.size() && j < b.size()) {
        const TimePs lo = std::max(a[i].begin, b[j].begin);
        const TimePs hi = std::min(a[i].end, b[j].end);
        if (hi > lo) out.push_back({lo, hi});
        if (a[i].end < b[j].end)
            ++i;
        else
            ++j;
    }
    return out;
}

TimePs total(const std::vector<TimeInterval>& v) {
    TimePs sum = 0;
    for (const TimeInterval& iv : v) sum += iv.end - iv.begin;
    return sum;
}

double ms(TimePs t) {
    return ps_to_s(t) * 1e3;
}

}  // namespace

void append_merged(std::vector<TimeInterval>& out, TimeInterval iv) {
    if (iv.end <= iv.begin) return;
    if (!out.empty() && out.back().end >= iv.begin) {
        out.back().end = std::max(out.back().end, iv.end);
    } else {
        out.push_back(iv);
    }
}

void SlowStretches::add(const ToolSample& sample, double feed_mm_per_min) {
    if (!m_last) {
        append_merged(m_slow, {std::numeric_limits<TimePs>::min(), sample.t_ps});
    } else if (const TimePs dt = sample.t_ps - m_last->t_ps; dt > 0) {
        const double dist_mm = geom::distance(m_last->pos, sample.pos);
        const double speed_mm_per_s = dist_mm / ps_to_s(dt);
        const bool slow = dist_mm == 0.0 || speed_mm_per_s < kDwellSpeedFraction * m_last_feed_mm_per_min / 60.0;
        if (slow) append_merged(m_slow, {m_last->t_ps, sample.t_ps});
    }
    m_last = sample;
    m_last_feed_mm_per_min = feed_mm_per_min;
}

std::vector<TimeInterval> SlowStretches::finish() {
    if (m_last) append_merged(m_slow, {m_last->t_ps, std::numeric_limits<TimePs>::max()});
    return std::move(m_slow);
}

void SlowStretches::drop_ending_by(TimePs t_ps) {
    const auto kept =
        std::find_if(m_slow.begin(), m_slow.end(), [t_ps](const TimeInterval& iv) { return iv.end > t_ps; });
    m_slow.erase(m_slow.begin(), kept);
}

void LaserFold::fold(const EdgeLog& laser, const std::vector<TimeInterval>& rapid,
                     const std::vector<TimeInterval>* slow, TimePs hi_ps) {
    if (hi_ps < m_lo_ps) return;
    // The on stretches lie inside the window, so each intersection counts only the window's part of an interval.
    const std::vector<TimeInterval> on = on_intervals(laser, m_lo_ps, hi_ps);
    m_lo_ps = hi_ps;
    m_on_ps += total(on);
    m_on_in_rapid_ps += total(intersect(on, rapid));
    if (!slow) return;
    for (const TimeInterval& iv : intersect(on, *slow)) {
        append_merged(m_open, iv);
        if (m_open.size() > 1) close_first_dwell();
    }
}

void LaserFold::close_first_dwell() {
    const TimeInterval iv = m_open.front();
    m_open.erase(m_open.begin());
    m_dwell_ps += iv.end - iv.begin;
    ++m_dwell_count;
    // The first of the longest, as std::max_element over the stretches in time order.
    if (!m_longest || iv.end - iv.begin > m_longest->end - m_longest->begin) m_longest = iv;
}

LaserResult LaserFold::finish(const EdgeLog& laser, TimePs t_job_end_ps,
                              const std::optional<std::vector<TimeInterval>>& rapid,
                              const std::optional<std::vector<TimeInterval>>& slow) {
    fold(laser, rapid.value_or(std::vector<TimeInterval>{}), slow ? &*slow : nullptr, t_job_end_ps);
    if (!m_open.empty()) close_first_dwell();
    LaserResult out;
    out.on_ms = ms(m_on_ps);
    if (!rapid) return out;
    out.on_in_rapid_ms = ms(m_on_in_rapid_ps);
    if (!slow) return out;
    out.dwell_ms = ms(m_dwell_ps);
    out.dwell_intervals = m_dwell_count;
    if (m_longest) {
        out.dwell_longest_ms = ms(m_longest->end - m_longest->begin);
        out.dwell_longest_at_s = ps_to_s(m_longest->begin);
    }
    return out;
}

LaserResult laser_result(const EdgeLog& laser, TimePs t_job_start_ps, TimePs t_job_end_ps,
                         const std::optional<std::vector<TimeInterval>>& rapid,
                         const std::optional<std::vector<TimeInterval>>& slow) {
    return LaserFold(t_job_start_ps).finish(laser, t_job_end_ps, rapid, slow);
}

std::optional<LaserResult> compute_laser(const RunInput& in, const EdgeIndex& idx) {
    if (!in.laser) return std::nullopt;
    if (in.moves.empty()) {
        return laser_result(*in.laser, in.t_job_start_ps, in.t_job_end_ps, std::nullopt, std::nullopt);
    }
    std::vector<TimeInterval> rapid;
    for (std::size_t m = 0; m < in.moves.size(); ++m) {
        if (in.moves[m].rapid && idx.move_first_edge_ps[m]) {
            append_merged(rapid, {*idx.move_first_edge_ps[m], *idx.move_last_edge_ps[m]});
        }
    }
    std::optional<std::vector<TimeInterval>> slow;
    if (!in.tool.empty()) {
        const MoveTimeline timeline(in.moves);
        SlowStretches stretches;
        for (const ToolSample& s : in.tool) {
            stretches.add(s, in.moves[timeline.active_at(s.t_ps).value_or(0)].feed_mm_per_min);
        }
        slow = stretches.finish();
    }
    return laser_result(*in.laser, in.t_job_start_ps, in.t_job_end_ps, rapid, slow);
}

}  // namespace cnc::metrics
