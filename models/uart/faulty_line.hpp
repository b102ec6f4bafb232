// A UART wire with faults on it (uart/core/line_faults.hpp): `out` follows `in` except inside a frame whose draw
// inverts some of its bits (the line's level inverted for those bit times, as the sender's bit clock places them)
// or loses it (the line held idle for the frame). A frame starts at a fall of an idle `in`; its bits are timed from
// that edge by the sender's bit clock, so the inversions cover whole bits at any baud. Noise on an idle line (a
// false start bit) is not drawn.
#pragma once
#include <cstdint>
#include <systemc>

#include "common/units.hpp"
#include "uart/core/line_faults.hpp"
#include "uart/core/uart_frame.hpp"

namespace cnc::uart {

struct FaultyLineStats {
    std::uint64_t frames = 0;         // frames that started on `in`
    std::uint64_t frames_hit = 0;     // with a bit inverted or lost whole
    std::uint64_t frames_lost = 0;    // lost whole
    std::uint64_t bits_inverted = 0;  // in the frames not lost
};

class FaultyLine : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> in;    // the sender's pin
    sc_core::sc_out<bool> out;  // what the receiver's pin sees; idles high

    // `sender`: the bit clock of the frames on `in`; `line`: tells this line's draws from the other lines' of `seed`.
    FaultyLine(const sc_core::sc_module_name& name, const LineFaultRates& rates, std::uint64_t seed, std::uint64_t line,
               BitClock sender, FrameFormat format = kFormat8N1);

    [[nodiscard]] const FaultyLineStats& stats() const { return m_stats; }
    // The earliest time `out` may change, asked at the current time, given the earliest time `in` may (what its
    // sender promises, >= now): `out` follows `in` but for a frame that is hit, where it changes at bit boundaries
    // too. For a receiver that runs ahead of the simulation time (models/fpga/rtl_loop.hpp).
    [[nodiscard]] TimePs out_quiet_until(TimePs in_quiet_until_ps) const;

private:
    void run();
    // Carries the frame whose start bit began now; true if `in` fell into the next frame's start bit before the
    // frame's last bit ended.
    bool carry_frame();

    LineFaultDraw m_draw;
    BitClock m_clock;
    int m_bits;
    FaultyLineStats m_stats;
    TimePs m_wake_ps = -1;      // the bit boundary the thread waits for within a frame that is hit, else -1
    TimePs m_boundary_ps = -1;  // the last bit boundary the thread woke at
};

}  // namespace cnc::uart
