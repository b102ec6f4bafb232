// The metrics of one run (docs/metrics.md), computed the same way for every architecture and for any VCD:
// compute_metrics() gathers the families (pulse, path, timing, laser); report/report.hpp writes them.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "metrics/laser/laser.hpp"
#include "metrics/move_metrics.hpp"
#include "metrics/path/path_accuracy.hpp"
#include "metrics/pulse/driver_timing.hpp"
#include "metrics/pulse/pulse_runs.hpp"
#include "metrics/run_input.hpp"
#include "metrics/timing/move_records.hpp"
#include "metrics/timing/move_timing.hpp"
#include "metrics/timing/worst_moves.hpp"

namespace cnc::metrics {

struct AxisMetrics {
    std::string name;         // x, y, ...
    std::string step_signal;  // EdgeLog names
    std::string dir_signal;
    std::size_t rising_edges = 0;
    std::size_t falling_edges = 0;
    std::size_t dir_changes = 0;
    std::int64_t net_steps = 0;               // rising edges signed by DIR
    std::optional<double> travel_mm, net_mm;  // steps_per_mm known
    std::size_t unattributed_edges = 0;       // with moves: rising edges before the first move
    std::vector<PulseRun> runs;
    AxisPulseSummary pulse;
    std::optional<double> sync_max_abs_ns;
    std::optional<std::size_t> sync_unmatched_edges;  // with a commanded trajectory (sync_error.hpp)
    DriverTimingReport driver;
};

// Worst over all axes.
struct PulseTotals {
    std::optional<double> jitter_std_max_ns, jitter_pp_max_ns;
    std::optional<double> tie_rms_max_ns, tie_max_ns, tie_max_period_frac;
    std::optional<double> rate_error_worst_pct;
    std::optional<double> sync_max_abs_ns;
    std::size_t driver_violations = 0;
};

struct RunMetrics {
    bool with_moves = false;
    bool with_tool = false;
    bool runs_per_rate_segment = false;  // RunInput::rate_segments given: runs are its segments, not moves
    double run_split_tolerance = 0.0;    // the analyze-mode setting the runs were split with
    std::vector<AxisMetrics> axes;
    MoveRecords moves;                // programmed moves (G-code lines)
    WorstMoves worst;                 // of the programmed moves
    std::vector<MoveMetrics> pieces;  // executed pieces (RunInput::moves): packets, chords, commands
    PulseTotals pulse;
    DriverLimits limits;
    PathResult path;      // per-piece parts moved into `pieces`
    TimingResult timing;  // per-programmed-move parts moved into `moves`
    std::optional<LaserResult> laser;
};

// Shared by compute_metrics and MetricsStream: an axis's distances from its counts and its pulse summary (of its
// runs, which the streaming metrics keep only for the detailed report), and the run's worst figures over the axes.
void finish_axis(AxisMetrics& am, double steps_per_mm, const AxisPulseSummary& pulse);
void add_axis_totals(PulseTotals& t, const AxisMetrics& am);

// Throws std::invalid_argument on inconsistent input (edge logs, moves or tool samples out of time order).
[[nodiscard]] RunMetrics compute_metrics(const RunInput& in);
}  // namespace cnc::metrics
