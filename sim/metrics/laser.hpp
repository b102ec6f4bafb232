// Laser exposure metrics: over-burn dwell (laser on while the tool is still or crawling) and laser on
// during rapid moves, which must be zero (DESIGN.md §4 "Laser").
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "metrics/edge_index.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

// Fraction of the move's F below which the tool counts as crawling (DESIGN.md §4: 10 % of F).
inline constexpr double kDwellSpeedFraction = 0.10;

struct LaserResult {
    double on_ms = 0.0;                 // laser on inside [t_job_start, t_job_end]
    std::optional<double> dwell_ms;     // needs tool samples and moves
    std::size_t dwell_intervals = 0;    // separate stretches of dwell
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

// Tool speed is piecewise constant between consecutive tool samples (distance / time); a stretch is
// slow when that speed is zero or below kDwellSpeedFraction of the F of the move active at its start.
// Before the first and after the last sample the tool is still. A rapid move's window is its first to
// its last rising STEP edge (any axis): laser on while a rapid has not started moving is dwell, not
// laser-in-rapid. Returns nullopt without a laser log.
[[nodiscard]] std::optional<LaserResult> compute_laser(const RunInput& in, const EdgeIndex& idx);

}  // namespace cnc::metrics
