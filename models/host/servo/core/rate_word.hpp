// A signed step rate -> the FPGA's rate word (models/spi/README.md: direction bit + period in FPGA clocks, rounded
// to the nearest clock by spi::period_for_rate), and back.
#pragma once
#include <cstdint>

#include "spi/core/spi_frame.hpp"

namespace cnc::host::servo {

// A rate whose period would not fit the word's 30-bit field (below clk / (2^30 - 1/2): 0.047 steps/s at 50 MHz,
// one step in 21.5 s) is sent as 0 = stopped, so the law's vanishing rates stop the axis. The caller keeps
// |rate| <= clk / min_period_cycles (the scenario refuses a velocity limit beyond it).
[[nodiscard]] spi::AxisRate rate_word_for(double steps_per_s, std::uint32_t clk_hz, std::uint32_t min_period_cycles);
// The same, but keeps `previous` (same direction, running) while clk / |rate| is within half a clock of its period
// (plus 1e-9 relative): at an exact half-clock tie (F800 at 160 steps/mm is 23,437.5 clocks at 50 MHz) the
// rounding would otherwise flip between two adjacent words on the last bits of the feed-forward velocity.
[[nodiscard]] spi::AxisRate rate_word_for(double steps_per_s, std::uint32_t clk_hz, std::uint32_t min_period_cycles,
                                          const spi::AxisRate& previous);
// The rate the generator runs at for a word: +-clk / period (forward positive), 0 when stopped.
[[nodiscard]] double signed_rate(const spi::AxisRate& word, std::uint32_t clk_hz);
[[nodiscard]] inline bool is_running(const spi::AxisRate& word) {
    return word.period_cycles != 0;
}

}  // namespace cnc::host::servo
