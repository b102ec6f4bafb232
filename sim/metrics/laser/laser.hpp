// Laser exposure metrics: over-burn dwell (laser on while the tool is still or crawling) and laser on
// during rapid moves, which must be zero (docs/metrics.md "Laser").
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "metrics/pulse/edge_index.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

// Fraction of the move's F below which the tool counts as crawling (docs/metrics.md "Laser": 10 % of F).
inline constexpr double kDwellSpeedFraction = 0.10;

struct LaserResult {
    double on_ms = 0.0;               // laser on inside [t_job_start, t_job_end]
    std::optional<double> dwell_ms;   // needs tool samples and moves
    std::size_t dwell_intervals = 0;  // separate stretches of dwell
    std::optional<double> dwell_longest_ms;
    std::optional<double> dwell_longest_at_s;  // start of the longest stretch
    std::optional<double> on_in_rapid_ms;      // needs moves
};

struct TimeInterval {
    TimePs begin = 0;
    TimePs end = 0;
};

// Appends to sorted, disjoint intervals, merging an interval that touches or overlaps the last one.
void append_merged(std::vector<TimeInterval>& out, TimeInterval iv);

// The stretches where the tool is slow (see compute_laser), built sample by sample in time order, so that a run can
// drop its samples as it goes.
class SlowStretches {
public:
    // `feed_mm_per_min`: the F of the move active at the sample, which the stretch from it to the next one is
    // judged by.
    void add(const ToolSample& sample, double feed_mm_per_min);
    // Sorted, disjoint; before the first and after the last sample the tool is still. Empty without samples.
    [[nodiscard]] std::vector<TimeInterval> finish();
    // The stretches so far (up to the last sample), and dropping those that end by t_ps (LaserFold has read them).
    [[nodiscard]] const std::vector<TimeInterval>& so_far() const { return m_slow; }
    void drop_ending_by(TimePs t_ps);

private:
    std::vector<TimeInterval> m_slow;
    std::optional<ToolSample> m_last;
    double m_last_feed_mm_per_min = 0.0;
};

// The laser figures from the laser pin, the rapid moves' edge windows (sorted, disjoint; none without moves) and
// the slow stretches (none without tool samples).
[[nodiscard]] LaserResult laser_result(const EdgeLog& laser, TimePs t_job_start_ps, TimePs t_job_end_ps,
                                       const std::optional<std::vector<TimeInterval>>& rapid,
                                       const std::optional<std::vector<TimeInterval>>& slow);

// laser_result window by window (the streaming metrics; laser_result is the one-window case): each window's laser
// edges, and every rapid window and slow stretch that may overlap it, are folded, so that neither the laser log nor
// the intervals need be kept. Carried: the totals, the dwell stretch that may still grow into the next window, the
// number of the closed ones and the longest.
class LaserFold {
public:
    explicit LaserFold(TimePs t_job_start_ps) : m_lo_ps(t_job_start_ps) {}
    // The window [last horizon, hi_ps): `laser` holds its edges (initial: the level at its start); `rapid` and
    // `slow` every interval that begins before hi_ps and has not ended by the last horizon (slow: null without tool
    // samples, then no dwell is measured). hi_ps must not pass the job's end; a window that ends before the last
    // horizon is empty.
    void fold(const EdgeLog& laser, const std::vector<TimeInterval>& rapid, const std::vector<TimeInterval>* slow,
              TimePs hi_ps);
    // The last window, to the job's end; `rapid` none: the run has no moves (no rapid or dwell figure).
    [[nodiscard]] LaserResult finish(const EdgeLog& laser, TimePs t_job_end_ps,
                                     const std::optional<std::vector<TimeInterval>>& rapid,
                                     const std::optional<std::vector<TimeInterval>>& slow);

private:
    void close_first_dwell();

    TimePs m_lo_ps;
    TimePs m_on_ps = 0;
    TimePs m_on_in_rapid_ps = 0;
    TimePs m_dwell_ps = 0;          // closed stretches
    std::size_t m_dwell_count = 0;  // closed stretches
    std::optional<TimeInterval> m_longest;
    std::vector<TimeInterval> m_open;  // the last dwell stretch (at most one): the next window's may join it
};

// Tool speed is piecewise constant between consecutive tool samples (distance / time); a stretch is
// slow when that speed is zero or below kDwellSpeedFraction of the F of the move active at its start.
// Before the first and after the last sample the tool is still. A rapid move's window is its first to
// its last rising STEP edge (any axis): laser on while a rapid has not started moving is dwell, not
// laser-in-rapid. Returns nullopt without a laser log.
[[nodiscard]] std::optional<LaserResult> compute_laser(const RunInput& in, const EdgeIndex& idx);

}  // namespace cnc::metrics
