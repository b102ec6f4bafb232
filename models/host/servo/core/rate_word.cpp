#include "host/servo/core/rate_word.hpp"

#include <cmath>

namespace cnc::host::servo {

spi::AxisRate rate_word_for(double steps_per_s, std::uint32_t clk_hz, std::uint32_t min_period_cycles) {
    const double rate = std::fabs(steps_per_s);
    // period_for_rate refuses exactly these (its overflow test): stopped instead.
    if (rate == 0.0 || static_cast<double>(clk_hz) / rate >= static_cast<double>(spi::kMaxPeriodCycles) + 0.5) {
        return spi::AxisRate{0, true};
    }
    return spi::axis_rate_for(steps_per_s, clk_hz, min_period_cycles, "host: rate word");
}

spi::AxisRate rate_word_for(double steps_per_s, std::uint32_t clk_hz, std::uint32_t min_period_cycles,
                            const spi::AxisRate& previous) {
    const spi::AxisRate word = rate_word_for(steps_per_s, clk_hz, min_period_cycles);
    if (word.period_cycles == 0 || previous.period_cycles == 0 || word.forward != previous.forward) return word;
    const double exact = static_cast<double>(clk_hz) / std::fabs(steps_per_s);
    const double kept = static_cast<double>(previous.period_cycles);
    return std::fabs(exact - kept) <= 0.5 + 1e-9 * kept ? previous : word;
}

double signed_rate(const spi::AxisRate& word, std::uint32_t clk_hz) {
    const double r = spi::rate_for_period(word.period_cycles, clk_hz);
    return word.forward ? r : -r;
}

}  // namespace cnc::host::servo
