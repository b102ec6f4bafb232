// Speed words of seed 003 §5.2.4 / §5.5: a STEP rate is an 8-bit compare value of a CTC toggle timer,
// f_OCnA = f_clk / (2 N (1 + OCRnA)) (eq. 2.3), so one microstep of s mm per toggle period gives
// v = f s / (2 N (OCR + 1)) and the PC program sends OCR = f / (2 N (v / s)) - 1 with the fraction dropped
// (eqs. 4.73, 4.77, 5.1). 10.45 mm/s at s = 0.00625 mm, N = 1024: 3.67 -> 3 -> 12.207 mm/s (eq. 5.2).
#pragma once
#include <cstdint>

namespace cnc::host::cad2g {

struct TimerClock {
    double f_cpu_hz = 16'000'000.0;  // seed 003 §5.2.4: 16 MHz crystal
    int prescaler = 1024;            // seed 003 App. A3: TCCR0B = 0b101; the PC computes with 1024
};

struct Ocr {
    double exact = 0.0;          // f / (2 N v/s) - 1 (infinite for v = 0)
    std::int64_t truncated = 0;  // the fraction dropped, as the seed converts to binary (eq. 5.1)
    std::uint8_t value = 0;      // what the register gets: truncated, held to 0..255
    bool too_fast = false;       // exact < 0: v above the OCR = 0 speed, sent as 0
    bool too_slow = false;       // truncated > 255: v below the OCR = 255 speed, sent as 255
};

[[nodiscard]] Ocr ocr_for_speed(double speed_mm_per_s, double mm_per_step, TimerClock clk = {});
// Microsteps per second of an OCR: f / (2 N (OCR + 1)).
[[nodiscard]] double step_rate_hz(std::uint8_t ocr, TimerClock clk = {});
// mm/s of an OCR at s mm per microstep (eq. 5.2).
[[nodiscard]] double speed_mm_per_s(std::uint8_t ocr, double mm_per_step, TimerClock clk = {});
// CPU cycles of one STEP period: 2 N (OCR + 1).
[[nodiscard]] std::int64_t step_period_cycles(std::uint8_t ocr, TimerClock clk = {});

}  // namespace cnc::host::cad2g
