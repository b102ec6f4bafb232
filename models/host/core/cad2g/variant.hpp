// Which of seed 003 §5.6's proposed improvements the PC program and the firmware build carry (avr.variant).
#pragma once
#include "host/core/cad2g/speed.hpp"

namespace cnc::host::cad2g {

enum class Variant {
    Seed,     // the seed: every OCR truncated, each axis's speed on its own (eqs. 4.76-4.77)
    Rounded,  // §5.6 interpolation 1-3: OCR0A rounded, v_y = (dy/dx) v_x of the rounded OCR0A, OCR2A rounded
    Timer1Y,  // Rounded with §5.6 hardware 2: Y on Timer1 (16 bits, N = 1), the head on Timer2's pin (PB3)
};

// The avr.variant value.
[[nodiscard]] inline const char* variant_name(Variant v) {
    switch (v) {
        case Variant::Seed:
            return "seed";
        case Variant::Rounded:
            return "rounded";
        case Variant::Timer1Y:
            return "timer1-y";
    }
    return "?";
}

[[nodiscard]] inline OcrRounding rounding(Variant v) {
    return v == Variant::Seed ? OcrRounding::Truncate : OcrRounding::Nearest;
}

// Y's timer: Timer2 like X's Timer0 (the PC's clock `x`), or Timer1 at N = 1.
[[nodiscard]] inline TimerClock y_timer(Variant v, TimerClock x) {
    return v == Variant::Timer1Y ? TimerClock{x.f_cpu_hz, kTimer1N1.prescaler, kTimer1N1.ocr_max} : x;
}

}  // namespace cnc::host::cad2g
