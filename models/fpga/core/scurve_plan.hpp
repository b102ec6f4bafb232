// step_gen's S-curve plan for one move (fpga.ramp = "s-curve", core/step_ramp.hpp has the registers it drives):
// the clocks n_j of each jerk phase and n_a at the top acceleration, chosen once at the move's start (at once: a
// hardware search would take thousands of clocks, sim/architectures/fpga_uart/README.md "The S-curve"). The
// acceleration then climbs by the jerk register each clock for n_j clocks (never above the acceleration register),
// holds for n_a clocks and falls back for n_j: the velocity gains jerk x n_j x (n_j + 1 + n_a) in 2^-80 steps per
// clock before its truncation. The plan is the largest whose gain stays within the cruise's velocity less the start
// speed (never faster than the packet asks) and whose distance, twice over (the deceleration mirrors it), leaves the
// move's first and last steps: a move too short for the full acceleration or the cruise gets shorter jerk phases (or
// none) and no top phase.
#pragma once
#include <cstdint>

#include "fpga/core/ramp_stretch.hpp"

namespace cnc::fpga {

struct ScurvePlan {
    std::int64_t jerk_clocks = 0;  // n_j
    std::int64_t top_clocks = 0;   // n_a
    std::uint32_t jerk_reg = 0;

    [[nodiscard]] std::int64_t clocks() const { return 2 * jerk_clocks + top_clocks; }  // T
    // The acceleration's clocks from clock i (0 <= i < T) to the end of its phase: jerk x min(i + 1, n_j, T - i) in
    // 2^-80 steps per clock^2, rising, holding or falling by the jerk register; the same from either end, so the
    // deceleration takes them in the same order, `slowing`.
    [[nodiscard]] RampStretch stretch_at(std::int64_t i, bool slowing) const;
};

// start and cruise velocities in 2^-48 steps per clock, the acceleration register in 2^-48 steps per clock^2, the
// jerk register in 2^-80 steps per clock^3 (> 0), abs_dom the dominant axis' steps.
[[nodiscard]] ScurvePlan plan_scurve(std::uint64_t start, std::uint64_t cruise, std::uint32_t accel_reg,
                                     std::uint32_t jerk_reg, std::uint32_t abs_dom);

}  // namespace cnc::fpga
