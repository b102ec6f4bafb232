#include "fpga/core/laser_pwm.hpp"

#include <algorithm>
#include <cmath>

namespace cnc::fpga {

std::optional<std::uint32_t> laser_pwm_period_cycles(std::uint32_t clk_hz, double pwm_hz) {
    if (!(pwm_hz > 0.0)) return std::nullopt;
    const double cycles = static_cast<double>(clk_hz) / pwm_hz;
    const double whole = std::round(cycles);
    if (std::fabs(cycles - whole) > 1e-9 || whole < 1.0 || whole > 4294967295.0) return std::nullopt;
    return static_cast<std::uint32_t>(whole);
}

std::uint16_t laser_high_cycles(double s, double s_max, std::uint32_t period_cycles) {
    const double fraction = std::clamp(s, 0.0, s_max) / s_max;
    return static_cast<std::uint16_t>(std::lround(fraction * static_cast<double>(period_cycles)));
}

bool laser_pwm_high(std::int64_t since_restart, std::uint32_t high, std::uint32_t period_cycles) {
    return since_restart % std::int64_t{period_cycles} < std::int64_t{high};
}

std::optional<std::int64_t> laser_pwm_next_change(std::int64_t since_restart, std::uint32_t high,
                                                  std::uint32_t period_cycles) {
    if (high == 0 || high >= period_cycles) return std::nullopt;
    const std::int64_t phase = since_restart % std::int64_t{period_cycles};
    return phase < std::int64_t{high} ? std::int64_t{high} - phase : std::int64_t{period_cycles} - phase;
}

}  // namespace cnc::fpga
