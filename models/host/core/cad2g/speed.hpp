// Speed words of seed 003 §5.2.4 / §5.5: a STEP rate is the compare value of a CTC toggle timer,
// f_OCnA = f_clk / (2 N (1 + OCRnA)) (eq. 2.3), so one microstep of s mm per toggle period gives
// v = f s / (2 N (OCR + 1)) and the PC program sends OCR = f / (2 N (v / s)) - 1 with the fraction dropped
// (eqs. 4.73, 4.77, 5.1). 10.45 mm/s at s = 0.00625 mm, N = 1024: 3.67 -> 3 -> 12.207 mm/s (eq. 5.2).
// Seed 003 §5.6 proposes rounding to the nearest integer instead (error at most 0.5 LSB: 3.67 -> 4) and moving Y to
// the 16-bit Timer1 at N = 1 (OCR1A up to 65535).
#pragma once
#include <cstdint>

namespace cnc::host::cad2g {

struct TimerClock {
    double f_cpu_hz = 16'000'000.0;  // seed 003 §5.2.4: 16 MHz crystal
    int prescaler = 1024;            // seed 003 App. A3: TCCR0B = 0b101; the PC computes with 1024
    std::uint16_t ocr_max = 255;     // OCR0A / OCR2A are 8 bits (seed 003 §5.5); Timer1's OCR1A is 16
};

// Timer1 as seed 003 §5.6 proposes it for Y: 16 bits, N = 1 (ATmega328P data sheet §16: OCR1A, CS1 = 001).
inline constexpr TimerClock kTimer1N1{16'000'000.0, 1, 0xFFFF};

// How the PC program makes an integer of the exact compare value.
enum class OcrRounding {
    Truncate,  // the seed's: the fraction dropped (eq. 5.1), up to 1 LSB
    Nearest,   // seed 003 §5.6 improvements 1 and 3: up to 0.5 LSB
};

struct Ocr {
    double exact = 0.0;        // f / (2 N v/s) - 1 (infinite for v = 0)
    std::int64_t integer = 0;  // exact made an integer (truncated or rounded, OcrRounding)
    std::uint16_t value = 0;   // what the register gets: integer, held to 0..ocr_max
    bool too_fast = false;     // integer < 0: v above the OCR = 0 speed, sent as 0
    bool too_slow = false;     // integer > ocr_max: v below the OCR = ocr_max speed, sent as ocr_max
};

[[nodiscard]] Ocr ocr_for_speed(double speed_mm_per_s, double mm_per_step, TimerClock clk = {},
                                OcrRounding rounding = OcrRounding::Truncate);
// Microsteps per second of an OCR: f / (2 N (OCR + 1)).
[[nodiscard]] double step_rate_hz(std::uint16_t ocr, TimerClock clk = {});
// mm/s of an OCR at s mm per microstep (eq. 5.2).
[[nodiscard]] double speed_mm_per_s(std::uint16_t ocr, double mm_per_step, TimerClock clk = {});
// CPU cycles of one STEP period: 2 N (OCR + 1).
[[nodiscard]] std::int64_t step_period_cycles(std::uint16_t ocr, TimerClock clk = {});

}  // namespace cnc::host::cad2g
