// Waveform generation modes of the ATmega328P timers: datasheet Table 15-8 (Timer0), Table 16-4 (Timer1),
// Table 18-8 (Timer2), and the compare output mode tables 15-2..15-7 / 16-1..16-3 / 18-2..18-7.
#pragma once
#include <cstdint>

namespace cnc::avr {

enum class Wave { Normal, Ctc, FastPwm, PhaseCorrect, PhaseFreqCorrect };
enum class TopSource { Fixed, OcrA, Icr };
enum class OcrUpdate { Immediate, AtTop, AtBottom };

struct TimerMode {
    Wave wave = Wave::Normal;
    TopSource top_source = TopSource::Fixed;
    std::uint16_t fixed_top = 0xFF;  // TOP when top_source is Fixed (0xFF, 0x1FF, 0x3FF or 0xFFFF)
    OcrUpdate ocr_update = OcrUpdate::Immediate;
    bool com01_toggles_a = false;  // PWM modes with TOP = OCRA (or ICR1 for Timer1 mode 14): COMxA = 01 toggles OCxA

    [[nodiscard]] bool single_slope() const {
        return wave == Wave::Normal || wave == Wave::Ctc || wave == Wave::FastPwm;
    }
    [[nodiscard]] bool pwm() const { return wave != Wave::Normal && wave != Wave::Ctc; }
};

// WGM bits -> mode. The reserved encodings (Timer0/2 modes 4 and 6, Timer1 mode 13) run as Normal mode.
[[nodiscard]] TimerMode timer_mode_8bit(unsigned wgm);
[[nodiscard]] TimerMode timer_mode_16bit(unsigned wgm);

// What a compare match (and, in fast PWM, reaching BOTTOM) does to the OCnx output register.
enum class OcAction { None, Toggle, Clear, Set };

struct CompareOutput {
    bool connected = false;                   // the pin shows OCnx (when its DDR bit makes it an output)
    OcAction on_match_up = OcAction::None;    // match while counting up (all single-slope modes)
    OcAction on_match_down = OcAction::None;  // match while counting down (dual-slope modes)
    OcAction at_bottom = OcAction::None;      // fast PWM only: when the counter wraps to BOTTOM
};

[[nodiscard]] CompareOutput compare_output(const TimerMode& mode, unsigned com, bool channel_a);

}  // namespace cnc::avr
