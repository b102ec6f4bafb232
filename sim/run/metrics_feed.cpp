#include "run/metrics_feed.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace cnc::sim {

namespace {

// How far the metrics may fall behind the simulation, in slices (each at most a second of simulated time:
// simulate.cpp), while they wait for the carriage's samples: the edges and the workers' calls of those slices are
// held until then. Two let one axis's worker integrate a move while the other's still works through the move
// before (a square's sides); more only hold more for the metrics to measure once the simulation has ended.
constexpr std::size_t kSlicesBehind = 2;

metrics::RunInput shape(const EdgeRecorder& rec, const std::vector<AxisPins>& axes, const std::string& laser_pin) {
    metrics::RunInput in;
    for (const AxisPins& a : axes) {
        const EdgeLog& step = rec.log(a.step_pin);
        const EdgeLog& dir = rec.log(a.dir_pin);
        in.axes.push_back({a.name,
                           {step.name, step.initial, {}},
                           {dir.name, dir.initial, {}},
                           a.steps_per_mm,
                           a.dir_high_is_positive});
    }
    const EdgeLog& laser = rec.log(laser_pin);
    in.laser = EdgeLog{laser.name, laser.initial, {}};
    return in;
}

void append(EdgeLog& to, const EdgeLog& from) {
    to.edges.insert(to.edges.end(), from.edges.begin(), from.edges.end());
}

}  // namespace

MetricsFeed::MetricsFeed(EdgeRecorder& rec, const std::vector<AxisPins>& axes, const std::string& laser_pin,
                         TakeSamplesBefore take_samples, bool detail, metrics::PieceMeasured on_piece)
    : m_axes(axes),
      m_laser_pin(laser_pin),
      m_take_samples(std::move(take_samples)),
      m_take_edges([&rec](const std::string& pin, TimePs t_ps) { return rec.take_before(pin, t_ps); }),
      m_stream(shape(rec, axes, laser_pin), detail, std::move(on_piece)) {}

void MetricsFeed::take_until(TimePs t_ps) {
    metrics::RunInput& p = m_stream.pending();
    for (std::size_t a = 0; a < m_axes.size(); ++a) {
        append(p.axes[a].step, m_take_edges(m_axes[a].step_pin, t_ps));
        append(p.axes[a].dir, m_take_edges(m_axes[a].dir_pin, t_ps));
    }
    append(*p.laser, m_take_edges(m_laser_pin, t_ps));
    const std::vector<ToolSample> samples = m_take_samples(t_ps);
    p.tool.insert(p.tool.end(), samples.begin(), samples.end());
}

void MetricsFeed::fold(TimePs now_ps) {
    if (m_ready) {
        m_slice_ends_ps.push_back(now_ps);
        now_ps = m_ready();
        if (m_slice_ends_ps.size() > kSlicesBehind)
            now_ps = std::max(now_ps, m_slice_ends_ps[m_slice_ends_ps.size() - 1 - kSlicesBehind]);
        while (!m_slice_ends_ps.empty() && m_slice_ends_ps.front() <= now_ps) m_slice_ends_ps.pop_front();
        if (now_ps <= m_measured_ps) return;
    }
    m_measured_ps = now_ps;
    take_until(now_ps);
    m_stream.pending().t_job_end_ps = now_ps;
    m_stream.fold(now_ps);
}

metrics::RunMetrics MetricsFeed::finish(TimePs t_job_end_ps) {
    take_until(std::numeric_limits<TimePs>::max());
    return m_stream.finish(t_job_end_ps);
}

void RateSegmentFeed::hand_over(MetricsFeed& feed, const std::vector<std::vector<metrics::RateSegment>>& segments) {
    metrics::RunInput& pending = feed.pending();
    pending.rate_segments.resize(segments.size());
    m_kept.resize(segments.size());
    for (std::size_t a = 0; a < segments.size(); ++a) {
        pending.rate_segments[a].insert(pending.rate_segments[a].end(), segments[a].begin(), segments[a].end());
        if (m_keep) m_kept[a].insert(m_kept[a].end(), segments[a].begin(), segments[a].end());
    }
}

}  // namespace cnc::sim
