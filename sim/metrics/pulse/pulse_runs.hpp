// Pulse-train quality per run (a stretch of one axis's rising STEP edges at one rate): period jitter, TIE against a
// least-squares recovered clock, and achieved against commanded step rate (docs/metrics.md "Pulse timing").
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "common/units.hpp"
#include "metrics/pulse/edge_index.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

struct PeriodStats {
    double mean_ns = 0.0;
    double std_ns = 0.0;  // population standard deviation of the periods
    double pp_ns = 0.0;   // longest minus shortest period
};

struct TieStats {
    double period_ns = 0.0;  // slope of the fitted grid t_k = a + b*k
    double rms_ns = 0.0;
    double max_abs_ns = 0.0;
};

// Needs n >= 2 edges.
[[nodiscard]] std::optional<PeriodStats> period_stats(const TimePs* t, std::size_t n);
// Needs n >= 3 edges (two points fit exactly). Centred sums in long double keep the residuals of an
// exact grid below 1e-3 ns even for runs of many seconds.
[[nodiscard]] std::optional<TieStats> tie_stats(const TimePs* t, std::size_t n);
// Each edge's TIE against the same fitted grid, ns (what the plots draw over time); empty below 3 edges.
[[nodiscard]] std::vector<double> tie_residuals_ns(const TimePs* t, std::size_t n);

// Analyze mode: a new run starts when a period differs from the mean period of the run so far by more
// than `tolerance` (relative), when it is more than 1.5x the previous period (a pause), or when DIR
// changed since the previous edge. The period across the split belongs to neither run.
[[nodiscard]] std::vector<EdgeRange> split_runs(const std::vector<TimePs>& rising,
                                                const std::vector<TimePs>& dir_changes, double tolerance);

struct PulseRun {
    std::optional<std::size_t> move;  // with moves: the move whose window holds the edges
    EdgeRange edges_range;            // indices into the axis's rising edges
    TimePs t_first_ps = 0;
    TimePs t_last_ps = 0;
    std::optional<PeriodStats> period;                 // >= 2 edges
    std::optional<TieStats> tie;                       // >= 3 edges
    std::optional<double> rate_achieved_steps_per_s;   // (n-1) / (t_last - t_first)
    std::optional<double> rate_commanded_steps_per_s;  // with moves, when the move commands a rate
    std::optional<double> rate_error_pct;              // (achieved - commanded) / commanded
    std::optional<double> speed_mm_per_min;            // achieved rate in mm when steps_per_mm is known

    [[nodiscard]] std::size_t edges() const { return edges_range.size(); }
};

struct AxisPulseSummary {
    std::size_t runs = 0;           // runs with at least one edge
    std::size_t runs_measured = 0;  // runs with period statistics (>= 2 edges)
    std::optional<double> jitter_std_max_ns, jitter_pp_max_ns;
    std::optional<double> tie_rms_max_ns, tie_max_ns, tie_max_period_frac;
    std::optional<double> rate_error_worst_pct;                  // signed, largest magnitude
    std::optional<std::size_t> worst_jitter_run, worst_tie_run;  // indices into the run list
};

// Runs of one axis: one per commanded rate segment with edges (RunInput::rate_segments: the commanded rate is the
// segment's, the move the one active at the run's first edge), else one per move with edges (with moves), else
// split by period (split_runs).
[[nodiscard]] std::vector<PulseRun> axis_runs(const RunInput& in, const EdgeIndex& idx, std::size_t axis);
[[nodiscard]] AxisPulseSummary summarise_runs(const std::vector<PulseRun>& runs);

// The summary folded run by run in order, so that the streaming metrics need not keep the runs (summarise_runs is
// the one-fold case).
class PulseSummaryFold {
public:
    void add(const PulseRun& r);
    [[nodiscard]] const AxisPulseSummary& summary() const { return m_out; }

private:
    AxisPulseSummary m_out;
};

}  // namespace cnc::metrics
