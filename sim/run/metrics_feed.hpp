// Hands what a run records to its streaming metrics (metrics/streaming/metrics_stream.hpp) at each slice boundary of
// simulate(): the STEP/DIR and laser edges the recorder took so far, the carriage's new tool samples, and the pieces
// the architecture says have ended. What the metrics have measured is dropped, so the logs stay short.
#pragma once
#include <cstddef>
#include <deque>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "common/tool_sample.hpp"
#include "metrics/streaming/metrics_stream.hpp"
#include "probes/edge_recorder.hpp"

namespace cnc::sim {

struct AxisPins {
    std::string name;               // x, y
    std::string step_pin, dir_pin;  // recorder pin names
    double steps_per_mm = 0.0;
    bool dir_high_is_positive = true;
};

// The carriage's tool samples taken before a time, handed over and forgotten there (mech::Carriage).
using TakeSamplesBefore = std::function<std::vector<ToolSample>(TimePs)>;
// The latest time before which the carriage's tool samples can be taken without waiting (mech::Carriage).
using SamplesReady = std::function<TimePs()>;
// A pin's edges before a time, handed over and forgotten there: the recorder's (EdgeRecorder::take_before), or what
// an architecture made of them (the STEP pulses its drivers take while their EN lets them).
using TakeEdgesBefore = std::function<EdgeLog(const std::string& pin, TimePs)>;

class MetricsFeed {
public:
    // Before the simulation starts: the recorder's logs give the pins' initial levels. `detail`, `on_piece`: as
    // metrics::MetricsStream's.
    MetricsFeed(EdgeRecorder& rec, const std::vector<AxisPins>& axes, const std::string& laser_pin,
                TakeSamplesBefore take_samples, bool detail, metrics::PieceMeasured on_piece = {});

    // Where the edges come from instead of the recorder (whose logs still give the pins' initial levels).
    void take_edges_with(TakeEdgesBefore take_edges) { m_take_edges = std::move(take_edges); }
    // A piece that began, in execution order, with its t_end_ps set once it has ended.
    void add_piece(metrics::MoveSpec piece) { m_stream.pending().moves.push_back(std::move(piece)); }
    // Where the run adds what else it knows so far: a commanded trajectory, rate segments (metrics_stream.hpp).
    [[nodiscard]] metrics::RunInput& pending() { return m_stream.pending(); }
    // Each fold measures up to where the carriage's samples are ready without waiting (`ready`), but never more
    // than kSlicesBehind slices behind the simulation: for a carriage whose axes run on worker threads
    // (mech::Carriage), which integrate what the simulation has run while it runs on, instead of the simulation
    // waiting for them at every slice. The edges must then be taken by their time (the recorder's take_before).
    void stay_behind(SamplesReady ready) { m_ready = std::move(ready); }
    // The simulation has reached now_ps (the job still runs).
    void fold(TimePs now_ps);
    // How far the folds have measured: what comes after it is still to be read (-1: nothing yet).
    [[nodiscard]] TimePs measured_ps() const { return m_measured_ps; }
    // The run has ended: everything left, and the metrics of the whole run.
    [[nodiscard]] metrics::RunMetrics finish(TimePs t_job_end_ps);
    [[nodiscard]] metrics::LaserExposure laser_exposure() const { return m_stream.laser_exposure(); }

private:
    void take_until(TimePs t_ps);

    std::vector<AxisPins> m_axes;
    std::string m_laser_pin;
    TakeSamplesBefore m_take_samples;
    TakeEdgesBefore m_take_edges;
    metrics::MetricsStream m_stream;
    SamplesReady m_ready;
    std::deque<TimePs> m_slice_ends_ps;  // with m_ready: the ends of the slices not yet measured to
    TimePs m_measured_ps = -1;
};

// The commanded rate segments of a controller that changes rates on its own schedule, handed to the streaming
// metrics as they are known (RunInput::rate_segments); with `keep` (--detail) also kept whole for the report's
// commanded rates, which the run's input hands over at its end.
class RateSegmentFeed {
public:
    explicit RateSegmentFeed(bool keep) : m_keep(keep) {}
    // [axis] the segments known since the last call, in time order.
    void hand_over(MetricsFeed& feed, const std::vector<std::vector<metrics::RateSegment>>& segments);
    // Every segment kept (one empty list per axis without `keep`): the report's commanded_rates, null then.
    [[nodiscard]] std::vector<std::vector<metrics::RateSegment>> take_kept() { return std::move(m_kept); }

private:
    bool m_keep;
    std::vector<std::vector<metrics::RateSegment>> m_kept;
};

}  // namespace cnc::sim
