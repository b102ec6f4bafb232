#include "avr/core/timer_unit.hpp"

#include <algorithm>

namespace cnc::avr {

namespace {

// Datasheet register layouts: TCCRnA = COMnA1:0 (7:6) COMnB1:0 (5:4) WGMn1:0 (1:0); TCCRnB = FOCnA (7) FOCnB (6)
// [Timer0/2] WGMn2 (3) CSn2:0 (2:0), Timer1: WGM13:12 (4:3); TCCR1C = FOC1A (7) FOC1B (6).
constexpr unsigned kComAShift = 6;
constexpr unsigned kComBShift = 4;
constexpr std::uint8_t kFocA = 0x80;
constexpr std::uint8_t kFocB = 0x40;

}  // namespace

TimerUnit::TimerUnit(const TimerSpec& spec, const Prescaler& prescaler, TimerSink& sink)
    : m_spec(spec), m_prescaler(prescaler), m_sink(&sink), m_mode(decode_mode()) {}

TimerUnit TimerUnit::copy_for(TimerSink& sink) const {
    TimerUnit copy(*this);
    copy.m_sink = &sink;
    return copy;
}

TimerMode TimerUnit::decode_mode() const {
    if (m_spec.sixteen_bit) return timer_mode_16bit((m_tccra & 3U) | ((m_tccrb >> 1) & 0x0CU));
    return timer_mode_8bit((m_tccra & 3U) | ((m_tccrb >> 1) & 0x04U));
}

std::uint16_t TimerUnit::top() const {
    const TimerMode m = mode();
    switch (m.top_source) {
        case TopSource::OcrA:
            return m_ocr[idx(Channel::A)];
        case TopSource::Icr:
            return m_icr;
        case TopSource::Fixed:
            break;
    }
    return std::min<std::uint16_t>(m.fixed_top, max());
}

CompareOutput TimerUnit::output(Channel ch) const {
    const unsigned com = (m_tccra >> (ch == Channel::A ? kComAShift : kComBShift)) & 3U;
    return compare_output(mode(), com, ch == Channel::A);
}

// Ticks until the counter first reads x (0 if it reads x now); none if it never will in the current mode.
std::optional<std::int64_t> TimerUnit::distance_to(std::uint16_t x) const {
    const std::int64_t v = m_tcnt;
    const std::int64_t t = top();
    const std::int64_t m = max();
    const std::int64_t to = x;
    if (mode().single_slope() || v > t) {
        // Up to the wrap value (TOP, or MAX once TOP was missed), then 0..TOP forever. A dual-slope counter above
        // TOP (TOP lowered under it) also runs up to MAX and wraps; from 0 it counts up, which the formula covers
        // for the values it reaches first.
        const std::int64_t wrap = v <= t ? t : m;
        if (to >= v && to <= wrap) return to - v;
        if (to <= t) return (wrap - v + 1) + to;
        return std::nullopt;
    }
    if (to > t) return std::nullopt;
    if (m_counting_up) return to >= v ? to - v : (t - v) + (t - to);
    return to <= v ? v - to : v + to;
}

std::optional<std::int64_t> TimerUnit::ticks_to_event() const {
    if (divisor() <= 0) return std::nullopt;
    // A blocked match is an event only where the counter holds a compare value: there it must be stepped (and not
    // matched); elsewhere the blocked tick is like any other.
    if (m_block_next_match && (m_tcnt == m_ocr[0] || m_tcnt == m_ocr[1])) return 1;
    std::optional<std::int64_t> best;
    const auto consider = [&](std::uint16_t x) {
        const auto d = distance_to(x);
        if (d && (!best || *d + 1 < *best)) best = *d + 1;  // the event is the tick that leaves x
    };
    const TimerMode m = mode();
    const std::uint16_t t = top();
    // Counting 0..TOP over and over, a tick whose every effect is a quiet flag changes nothing but the count,
    // which advance_quietly takes in closed form: it is no event.
    const bool skip = m_quiet_flags != 0 && counts_to_top(m) && m_ocr == m_ocr_buffer;
    const auto quiet_match = [&](Channel ch) {
        return output(ch).on_match_up == OcAction::None &&
               quiet(ch == Channel::A ? TimerFlag::CompareA : TimerFlag::CompareB);
    };
    const auto quiet_wrap = [&] {
        const bool tov = m.wave == Wave::FastPwm || t == max();
        const bool bottom_action = m.wave == Wave::FastPwm && (output(Channel::A).at_bottom != OcAction::None ||
                                                               output(Channel::B).at_bottom != OcAction::None);
        return (!tov || quiet(TimerFlag::Overflow)) && (m.top_source != TopSource::Icr || quiet(TimerFlag::Capture)) &&
               !bottom_action;
    };
    if (!skip || !quiet_match(Channel::A)) consider(m_ocr[0]);
    if (!skip || !quiet_match(Channel::B)) consider(m_ocr[1]);
    if (!skip || !quiet_wrap()) consider(t);
    if (!skip) consider(max());  // counting to TOP, MAX is only reached as TOP
    if (!m.single_slope()) consider(0);
    return best;
}

bool TimerUnit::counts_to_top(const TimerMode& m) const {
    return m.single_slope() && m_tcnt <= top();
}

std::optional<Cycle> TimerUnit::tick_cycle(std::int64_t k) const {
    const int n = divisor();
    if (n <= 0) return std::nullopt;
    const auto first = m_prescaler.first_tick_after(m_last, n);
    if (!first) return std::nullopt;
    return *first + (k - 1) * n;
}

std::int64_t TimerUnit::ticks_until(Cycle c) const {
    const int n = divisor();
    return n <= 0 ? 0 : m_prescaler.ticks_between(m_last, c, n);
}

void TimerUnit::set_quiet_flags(Cycle c, std::uint8_t mask) {
    if (mask == m_quiet_flags) return;
    advance_to(c);  // the ticks up to c under the mask they came under
    m_quiet_flags = mask;
    changed();
}

std::optional<Cycle> TimerUnit::next_event() const {
    if (!m_next_valid || m_next_epoch != m_prescaler.epoch()) {
        const auto k = ticks_to_event();
        m_next = k ? tick_cycle(*k) : std::nullopt;
        m_next_valid = true;
        m_next_epoch = m_prescaler.epoch();
    }
    return m_next;
}

// Ticks that are no event: the count only (a wrap at TOP included when counting 0..TOP).
void TimerUnit::advance_quietly(std::int64_t ticks) {
    if (ticks <= 0) return;
    m_block_next_match = false;  // the blocked tick is among them
    const TimerMode m = mode();
    if (counts_to_top(m)) {
        m_counting_up = true;  // as step() leaves it in a single-slope mode
        m_tcnt = static_cast<std::uint16_t>((m_tcnt + ticks) % (std::int64_t{top()} + 1));
        return;
    }
    // A single-slope counter above TOP counts up to MAX, and a dual-slope counter above TOP (TOP lowered under it)
    // also counts up (and a later dual-slope mode continues up).
    const bool up = m.single_slope() || m_counting_up || m_tcnt > top();
    m_counting_up = up;
    m_tcnt = static_cast<std::uint16_t>(up ? m_tcnt + ticks : m_tcnt - ticks);
}

void TimerUnit::advance_to(Cycle c) {
    for (auto t = next_event(); t && *t <= c; t = next_event()) {
        advance_quietly(ticks_until(*t) - 1);
        step(*t);
        m_last = *t;
    }
    advance_quietly(ticks_until(c));
    m_last = std::max(m_last, c);
}

void TimerUnit::apply(Channel ch, OcAction a, Cycle c) {
    bool& oc = m_oc[idx(ch)];
    const bool before = oc;
    switch (a) {
        case OcAction::None:
            return;
        case OcAction::Toggle:
            oc = !oc;
            break;
        case OcAction::Clear:
            oc = false;
            break;
        case OcAction::Set:
            oc = true;
            break;
    }
    if (oc != before && output(ch).connected) m_sink->timer_output(m_spec.name, c);
}

// One timer clock tick at cycle c that leaves the value the counter held during the previous timer clock.
void TimerUnit::step(Cycle c) {
    ++m_event_ticks;
    changed();
    const TimerMode m = mode();
    const std::uint16_t v = m_tcnt;
    const std::uint16_t t = top();
    const bool blocked = m_block_next_match;
    m_block_next_match = false;
    const bool match_a = !blocked && v == m_ocr[0];
    const bool match_b = !blocked && v == m_ocr[1];

    std::uint16_t next = 0;
    bool up_step = true;
    bool leaves_top = false;
    bool leaves_bottom = false;
    bool wraps_at_max = false;
    if (m.single_slope() || v > t) {
        m_counting_up = true;  // a dual-slope counter above TOP runs up to MAX, wraps, and counts up from 0
        leaves_top = v == t;
        wraps_at_max = !leaves_top && v == max();
        next = (leaves_top || wraps_at_max) ? 0 : static_cast<std::uint16_t>(v + 1);
    } else if (t == 0) {  // degenerate dual slope: the counter stays at BOTTOM = TOP
        leaves_top = leaves_bottom = true;
    } else if (m_counting_up) {
        leaves_top = v == t;
        up_step = !leaves_top;
        m_counting_up = !leaves_top;
        next = static_cast<std::uint16_t>(leaves_top ? v - 1 : v + 1);
    } else {
        leaves_bottom = v == 0;
        up_step = leaves_bottom;
        m_counting_up = leaves_bottom;
        next = static_cast<std::uint16_t>(leaves_bottom ? 1 : v - 1);
    }
    m_tcnt = next;

    for (const Channel ch : {Channel::A, Channel::B}) {
        if (!(ch == Channel::A ? match_a : match_b)) continue;
        const CompareOutput out = output(ch);
        apply(ch, up_step ? out.on_match_up : out.on_match_down, c);
    }
    const bool wrapped = next == 0 && (leaves_top || wraps_at_max) && m.single_slope();
    if (m.wave == Wave::FastPwm && wrapped) {  // BOTTOM action after the match: OCR = TOP gives a constant level
        for (const Channel ch : {Channel::A, Channel::B}) apply(ch, output(ch).at_bottom, c);
    }

    if (match_a) m_sink->timer_flag(m_spec.name, TimerFlag::CompareA, c);
    if (match_b) m_sink->timer_flag(m_spec.name, TimerFlag::CompareB, c);
    const bool tov = [&] {
        switch (m.wave) {
            case Wave::Normal:
            case Wave::Ctc:
                return v == max();
            case Wave::FastPwm:
                return leaves_top || wraps_at_max;
            default:
                return leaves_bottom;
        }
    }();
    if (tov) m_sink->timer_flag(m_spec.name, TimerFlag::Overflow, c);
    if (leaves_top && m.top_source == TopSource::Icr) m_sink->timer_flag(m_spec.name, TimerFlag::Capture, c);

    const bool update = (m.ocr_update == OcrUpdate::AtBottom && (wrapped || leaves_bottom)) ||
                        (m.ocr_update == OcrUpdate::AtTop && leaves_top);
    if (update) m_ocr = m_ocr_buffer;
}

bool TimerUnit::any_output_connected() const {
    return output(Channel::A).connected || output(Channel::B).connected;
}

void TimerUnit::mode_changed(Cycle c, bool was_connected) {
    m_mode = decode_mode();
    if (!mode().pwm()) m_ocr = m_ocr_buffer;
    // With no compare output connected before or after, every pin still shows its PORT bit.
    if (was_connected || any_output_connected()) m_sink->timer_output(m_spec.name, c);
}

void TimerUnit::write_tccra(Cycle c, std::uint8_t v) {
    advance_to(c);
    changed();
    const bool was_connected = any_output_connected();
    m_tccra = v;
    mode_changed(c, was_connected);
}

void TimerUnit::write_tccrb(Cycle c, std::uint8_t v) {
    advance_to(c);
    changed();
    const bool was_connected = any_output_connected();
    // Timer1 keeps ICNC1/ICES1 in bits 7:6 (input capture is not modelled, but the bits read back).
    m_tccrb = m_spec.sixteen_bit ? v : static_cast<std::uint8_t>(v & ~(kFocA | kFocB));
    mode_changed(c, was_connected);
    const auto force = static_cast<std::uint8_t>(v & (kFocA | kFocB));
    if (!m_spec.sixteen_bit && force != 0) write_tccrc(c, force);
}

void TimerUnit::write_tccrc(Cycle c, std::uint8_t v) {
    advance_to(c);
    if (mode().pwm()) return;  // datasheet: FOCnx is only active in non-PWM modes
    if ((v & kFocA) != 0) apply(Channel::A, output(Channel::A).on_match_up, c);
    if ((v & kFocB) != 0) apply(Channel::B, output(Channel::B).on_match_up, c);
}

void TimerUnit::write_tcnt(Cycle c, std::uint16_t v) {
    advance_to(c);
    changed();
    m_tcnt = static_cast<std::uint16_t>(v & max());
    m_block_next_match = true;
}

void TimerUnit::write_ocr(Cycle c, Channel ch, std::uint16_t v) {
    advance_to(c);
    changed();
    m_ocr_buffer[idx(ch)] = static_cast<std::uint16_t>(v & max());
    if (!mode().pwm()) m_ocr[idx(ch)] = m_ocr_buffer[idx(ch)];
}

void TimerUnit::write_icr(Cycle c, std::uint16_t v) {
    advance_to(c);
    changed();
    m_icr = v;
}

std::uint16_t TimerUnit::read_tcnt(Cycle c) {
    advance_to(c);
    return m_tcnt;
}

}  // namespace cnc::avr
