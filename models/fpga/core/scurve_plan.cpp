#include "fpga/core/scurve_plan.hpp"

#include <algorithm>
#include <cmath>

#include "fpga/core/step_ramp.hpp"

namespace cnc::fpga {

namespace {

__extension__ typedef unsigned __int128 Wide;

// The largest plan whose untruncated gain jerk x n_j x (n_j + 1 + n_a) is at most `gain`, n_j <= jerk_max.
ScurvePlan largest_within(Wide gain, std::uint32_t jerk, std::int64_t jerk_max) {
    ScurvePlan p;
    p.jerk_reg = jerk;
    const auto fits = [&](std::int64_t n) { return Wide{jerk} * Wide(n) * Wide(n + 1) <= gain; };
    auto n = static_cast<std::int64_t>(std::sqrt(static_cast<double>(gain) / jerk));
    n = std::min(n + 1, jerk_max);
    while (n > 0 && !fits(n)) --n;
    if (n == 0) return p;
    p.jerk_clocks = n;
    p.top_clocks = static_cast<std::int64_t>(gain / (Wide{jerk} * Wide(n))) - n - 1;
    return p;
}

// Whether the acceleration and its mirror leave the first and the last step: each covers
// T start + (T - 1) gain / 2 in the phase (an upper bound: the increments are truncated), at most abs_dom / 2 - 1
// steps.
bool fits_move(const ScurvePlan& p, std::uint64_t start, std::uint32_t abs_dom) {
    const Wide t(p.clocks());
    const Wide gain = Wide{p.jerk_reg} * Wide(p.jerk_clocks) * Wide(p.jerk_clocks + 1 + p.top_clocks) >> kJerkShift;
    const Wide twice_distance = 2 * t * start + (t == 0 ? 0 : (t - 1) * gain);
    return twice_distance + 2 * Wide{kPhaseOne} <= Wide{abs_dom} * kPhaseOne;
}

}  // namespace

RampStretch ScurvePlan::stretch_at(std::int64_t i, bool slowing) const {
    const std::uint64_t jerk = jerk_reg;
    if (i < jerk_clocks) return {jerk * static_cast<std::uint64_t>(i + 1), jerk_reg, slowing, jerk_clocks - i};
    const std::int64_t top_end = jerk_clocks + top_clocks;
    if (i < top_end) return {jerk * static_cast<std::uint64_t>(jerk_clocks), 0, slowing, top_end - i};
    return {jerk * static_cast<std::uint64_t>(clocks() - i), -std::int64_t{jerk_reg}, slowing, clocks() - i};
}

ScurvePlan plan_scurve(std::uint64_t start, std::uint64_t cruise, std::uint32_t accel_reg, std::uint32_t jerk_reg,
                       std::uint32_t abs_dom) {
    if (cruise <= start || jerk_reg == 0) return {0, 0, jerk_reg};
    const auto jerk_max = static_cast<std::int64_t>((std::uint64_t{accel_reg} << kJerkShift) / jerk_reg);
    const Wide full = Wide{cruise - start} << kJerkShift;
    ScurvePlan p = largest_within(full, jerk_reg, jerk_max);
    if (fits_move(p, start, abs_dom)) return p;
    // A short move: the largest gain whose plan fits (the distance grows with the gain).
    Wide lo = 0;
    Wide hi = full;
    while (lo < hi) {
        const Wide mid = lo + (hi - lo + 1) / 2;
        if (fits_move(largest_within(mid, jerk_reg, jerk_max), start, abs_dom)) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    return largest_within(lo, jerk_reg, jerk_max);
}

}  // namespace cnc::fpga
