// Time and unit conventions shared by every model: SystemC-free, integer picoseconds (SystemC's default time
// resolution), so that 20 ns FPGA cycles and 62.5 ns AVR cycles are exact.
#pragma once
#include <cstdint>

namespace cnc {

using TimePs = std::int64_t;

inline constexpr TimePs kPsPerNs = 1'000;
inline constexpr TimePs kPsPerUs = 1'000'000;
inline constexpr TimePs kPsPerMs = 1'000'000'000;
inline constexpr TimePs kPsPerSec = 1'000'000'000'000;
inline constexpr double kSecondsPerMinute = 60.0;  // feeds are mm/min (G94), speeds mm/s

// Time of `cycles` ticks of a clock of `clk_hz`, rounded down to the picosecond. Exact for clocks whose
// period is a whole number of ps (50 MHz -> 20 000 ps, 16 MHz -> 62 500 ps); for others (the CP2102's
// 24 MHz) the multiplication comes first, so there is no cumulative drift over long runs.
constexpr TimePs cycles_to_ps(std::int64_t cycles, std::int64_t clk_hz) {
    // Split so that no product overflows int64 for clocks below 1 GHz: part * 1e6 < 1e15.
    const std::int64_t whole = cycles / clk_hz;
    const std::int64_t part_us = (cycles % clk_hz) * 1'000'000;
    return whole * kPsPerSec + (part_us / clk_hz) * 1'000'000 + (part_us % clk_hz) * 1'000'000 / clk_hz;
}

// Index of the first clock edge strictly after `t_ps` (edges at n * period, n >= 0): the edge that
// samples a level that changed at `t_ps` (a change exactly on an edge is seen by the next one).
constexpr std::int64_t first_edge_after(TimePs t_ps, TimePs period_ps) {
    return t_ps < 0 ? 0 : t_ps / period_ps + 1;
}

// Seconds to the nearest picosecond.
inline TimePs s_to_ps(double s) {
    return static_cast<TimePs>(s * static_cast<double>(kPsPerSec) + 0.5);
}
inline double ps_to_s(TimePs t) {
    return static_cast<double>(t) / static_cast<double>(kPsPerSec);
}
inline double ps_to_us(TimePs t) {
    return static_cast<double>(t) / static_cast<double>(kPsPerUs);
}
inline double ps_to_ns(TimePs t) {
    return static_cast<double>(t) / static_cast<double>(kPsPerNs);
}

}  // namespace cnc
