#include "uart/faulty_line.hpp"

#include <algorithm>
#include <bitset>

#include "common/sc_time.hpp"

namespace cnc::uart {

FaultyLine::FaultyLine(const sc_core::sc_module_name& name, const LineFaultRates& rates, std::uint64_t seed,
                       std::uint64_t line, BitClock sender, FrameFormat format)
    : sc_module(name),
      in("in"),
      out("out"),
      m_draw(rates, seed, line),
      m_clock(sender),
      m_bits((validate(format), format.bits_per_frame())) {
    SC_HAS_PROCESS(FaultyLine);
    out.initialize(true);
    SC_THREAD(run);
}

void FaultyLine::run() {
    bool next_frame = false;
    for (;;) {
        if (!next_frame) {
            sc_core::wait(in.value_changed_event());
            if (in.read()) {
                out.write(true);
                continue;
            }
        }
        next_frame = carry_frame();
    }
}

bool FaultyLine::carry_frame() {
    const TimePs t0 = now_ps();
    const FrameFault f = m_draw.frame(m_stats.frames++, m_bits);
    if (f.hit()) ++m_stats.frames_hit;
    if (f.lost)
        ++m_stats.frames_lost;
    else
        m_stats.bits_inverted += std::bitset<32>(f.inverted_bits).count();
    const TimePs t_end = t0 + m_clock.bit_edge(m_bits);
    // A fall after the middle of the last stop bit is the next frame's start bit (a sender a little fast).
    const TimePs t_next_frame = t0 + m_clock.mid_bit(m_bits - 1);
    int bit = 0;
    for (;;) {
        const TimePs now = now_ps();
        // Woken at a bit boundary: what `out` is written now is seen a delta later (out_quiet_until).
        if (!in.event()) m_boundary_ps = now;
        if (now >= t_next_frame && in.negedge()) return true;
        if (now >= t_end) break;
        while (t0 + m_clock.bit_edge(bit + 1) <= now) ++bit;
        const bool inverted = ((f.inverted_bits >> bit) & 1U) != 0;
        out.write(f.lost || (in.read() != inverted));
        // A frame left whole needs no wake but the sender's edges.
        const TimePs wake = f.hit() ? t0 + m_clock.bit_edge(bit + 1) : t_end;
        m_wake_ps = f.hit() ? wake : -1;
        sc_core::wait(ps_time(wake - now), in.value_changed_event());
    }
    m_wake_ps = -1;
    out.write(in.read());
    return false;
}

TimePs FaultyLine::out_quiet_until(TimePs in_quiet_until_ps) const {
    const TimePs now = now_ps();
    if (now == m_boundary_ps) return now;  // a level written at this boundary may not be seen yet
    if (m_wake_ps < 0) return in_quiet_until_ps;
    return std::min(in_quiet_until_ps, std::max(now, m_wake_ps));
}

}  // namespace cnc::uart
