#include "host/core/cad2g/speed.hpp"

#include <cmath>
#include <limits>

namespace cnc::host::cad2g {

Ocr ocr_for_speed(double speed_mm_per_s, double mm_per_step, TimerClock clk) {
    Ocr o;
    const double steps_per_s = speed_mm_per_s / mm_per_step;
    o.exact = steps_per_s > 0.0 ? clk.f_cpu_hz / (2.0 * clk.prescaler * steps_per_s) - 1.0
                                : std::numeric_limits<double>::infinity();
    if (o.exact < 0.0) {
        o.too_fast = true;
        o.truncated = static_cast<std::int64_t>(std::trunc(o.exact));
        o.value = 0;
    } else if (o.exact >= 256.0) {
        o.too_slow = true;
        o.truncated = std::isfinite(o.exact) && o.exact < 9.0e18 ? static_cast<std::int64_t>(o.exact)
                                                                 : std::numeric_limits<std::int64_t>::max();
        o.value = 255;
    } else {
        o.truncated = static_cast<std::int64_t>(o.exact);
        o.value = static_cast<std::uint8_t>(o.truncated);
    }
    return o;
}

std::int64_t step_period_cycles(std::uint8_t ocr, TimerClock clk) {
    return 2 * static_cast<std::int64_t>(clk.prescaler) * (static_cast<std::int64_t>(ocr) + 1);
}

double step_rate_hz(std::uint8_t ocr, TimerClock clk) {
    return clk.f_cpu_hz / static_cast<double>(step_period_cycles(ocr, clk));
}

double speed_mm_per_s(std::uint8_t ocr, double mm_per_step, TimerClock clk) {
    return step_rate_hz(ocr, clk) * mm_per_step;
}

}  // namespace cnc::host::cad2g
