#include "host/core/cad2g/speed.hpp"

#include <cmath>
#include <limits>

namespace cnc::host::cad2g {

namespace {

// exact finite and within +-2^63 (the cast truncates toward zero).
std::int64_t to_integer(double exact, OcrRounding rounding) {
    return static_cast<std::int64_t>(rounding == OcrRounding::Nearest ? std::floor(exact + 0.5) : exact);
}

}  // namespace

Ocr ocr_for_speed(double speed_mm_per_s, double mm_per_step, TimerClock clk, OcrRounding rounding) {
    Ocr o;
    const double steps_per_s = speed_mm_per_s / mm_per_step;
    o.exact = steps_per_s > 0.0 ? clk.f_cpu_hz / (2.0 * clk.prescaler * steps_per_s) - 1.0
                                : std::numeric_limits<double>::infinity();
    // -0.5 rounds to 0: a speed within half an LSB above the OCR = 0 speed is not too fast.
    const double lowest = rounding == OcrRounding::Nearest ? -0.5 : 0.0;
    if (o.exact < lowest) {
        o.too_fast = true;
        o.integer = to_integer(o.exact, rounding);
        o.value = 0;
        return o;
    }
    o.integer = std::isfinite(o.exact) && o.exact < 9.0e18 ? to_integer(o.exact, rounding)
                                                           : std::numeric_limits<std::int64_t>::max();
    if (o.integer > clk.ocr_max) {
        o.too_slow = true;
        o.value = clk.ocr_max;
    } else {
        o.value = static_cast<std::uint16_t>(o.integer);
    }
    return o;
}

std::int64_t step_period_cycles(std::uint16_t ocr, TimerClock clk) {
    return 2 * static_cast<std::int64_t>(clk.prescaler) * (static_cast<std::int64_t>(ocr) + 1);
}

double step_rate_hz(std::uint16_t ocr, TimerClock clk) {
    return clk.f_cpu_hz / static_cast<double>(step_period_cycles(ocr, clk));
}

double speed_mm_per_s(std::uint16_t ocr, double mm_per_step, TimerClock clk) {
    return step_rate_hz(ocr, clk) * mm_per_step;
}

}  // namespace cnc::host::cad2g
