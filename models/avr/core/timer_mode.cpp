#include "avr/core/timer_mode.hpp"

namespace cnc::avr {

namespace {

constexpr TimerMode normal(std::uint16_t max) {
    return {Wave::Normal, TopSource::Fixed, max, OcrUpdate::Immediate, false};
}

}  // namespace

TimerMode timer_mode_8bit(unsigned wgm) {
    switch (wgm & 7U) {
        case 1:
            return {Wave::PhaseCorrect, TopSource::Fixed, 0xFF, OcrUpdate::AtTop, false};
        case 2:
            return {Wave::Ctc, TopSource::OcrA, 0xFF, OcrUpdate::Immediate, false};
        case 3:
            return {Wave::FastPwm, TopSource::Fixed, 0xFF, OcrUpdate::AtBottom, false};
        case 5:
            return {Wave::PhaseCorrect, TopSource::OcrA, 0xFF, OcrUpdate::AtTop, true};
        case 7:
            return {Wave::FastPwm, TopSource::OcrA, 0xFF, OcrUpdate::AtBottom, true};
        default:
            return normal(0xFF);
    }
}

TimerMode timer_mode_16bit(unsigned wgm) {
    switch (wgm & 15U) {
        case 1:
            return {Wave::PhaseCorrect, TopSource::Fixed, 0x00FF, OcrUpdate::AtTop, false};
        case 2:
            return {Wave::PhaseCorrect, TopSource::Fixed, 0x01FF, OcrUpdate::AtTop, false};
        case 3:
            return {Wave::PhaseCorrect, TopSource::Fixed, 0x03FF, OcrUpdate::AtTop, false};
        case 4:
            return {Wave::Ctc, TopSource::OcrA, 0xFFFF, OcrUpdate::Immediate, false};
        case 5:
            return {Wave::FastPwm, TopSource::Fixed, 0x00FF, OcrUpdate::AtBottom, false};
        case 6:
            return {Wave::FastPwm, TopSource::Fixed, 0x01FF, OcrUpdate::AtBottom, false};
        case 7:
            return {Wave::FastPwm, TopSource::Fixed, 0x03FF, OcrUpdate::AtBottom, false};
        case 8:
            return {Wave::PhaseFreqCorrect, TopSource::Icr, 0xFFFF, OcrUpdate::AtBottom, false};
        case 9:
            return {Wave::PhaseFreqCorrect, TopSource::OcrA, 0xFFFF, OcrUpdate::AtBottom, true};
        case 10:
            return {Wave::PhaseCorrect, TopSource::Icr, 0xFFFF, OcrUpdate::AtTop, false};
        case 11:
            return {Wave::PhaseCorrect, TopSource::OcrA, 0xFFFF, OcrUpdate::AtTop, true};
        case 12:
            return {Wave::Ctc, TopSource::Icr, 0xFFFF, OcrUpdate::Immediate, false};
        case 14:
            return {Wave::FastPwm, TopSource::Icr, 0xFFFF, OcrUpdate::AtBottom, true};
        case 15:
            return {Wave::FastPwm, TopSource::OcrA, 0xFFFF, OcrUpdate::AtBottom, true};
        default:
            return normal(0xFFFF);
    }
}

CompareOutput compare_output(const TimerMode& mode, unsigned com, bool channel_a) {
    CompareOutput out;
    com &= 3U;
    if (com == 0) return out;
    if (!mode.pwm()) {  // Tables 15-2 / 16-1 / 18-2: toggle, clear, set on compare match
        const OcAction a = com == 1 ? OcAction::Toggle : com == 2 ? OcAction::Clear : OcAction::Set;
        return {true, a, a, OcAction::None};
    }
    if (com == 1) {  // toggles OCnA only with WGMn2 (WGM13) set; otherwise a normal port pin
        if (!(channel_a && mode.com01_toggles_a)) return out;
        return {true, OcAction::Toggle, OcAction::Toggle, OcAction::None};
    }
    const bool non_inverting = com == 2;
    const OcAction on_match = non_inverting ? OcAction::Clear : OcAction::Set;
    const OcAction other = non_inverting ? OcAction::Set : OcAction::Clear;
    if (mode.wave == Wave::FastPwm) return {true, on_match, on_match, other};  // Tables 15-3 / 16-2 / 18-3
    return {true, on_match, other, OcAction::None};  // phase (and frequency) correct: Tables 15-4 / 16-3 / 18-4
}

}  // namespace cnc::avr
