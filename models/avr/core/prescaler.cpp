#include "avr/core/prescaler.hpp"

namespace cnc::avr {

namespace {

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

}  // namespace

std::optional<Cycle> Prescaler::first_tick_after(Cycle after, int divisor) const {
    if (divisor == 1) return after + 1;
    if (m_held) return std::nullopt;
    return m_origin + (floor_div(after - m_origin, divisor) + 1) * divisor;
}

std::int64_t Prescaler::ticks_between(Cycle from, Cycle to, int divisor) const {
    if (to <= from) return 0;
    if (divisor == 1) return to - from;
    if (m_held) return 0;
    return floor_div(to - m_origin, divisor) - floor_div(from - m_origin, divisor);
}

void Prescaler::restart(Cycle c) {
    m_origin = c;
    m_held = false;
    ++m_epoch;
}

void Prescaler::hold(Cycle c) {
    m_origin = c;
    m_held = true;
    ++m_epoch;
}

void Prescaler::release(Cycle c) {
    if (!m_held) return;
    restart(c);
}

}  // namespace cnc::avr
