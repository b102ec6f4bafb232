// The clock prescaler in front of the ATmega328P timers. Datasheet §17 (Timer/Counter0 and Timer/Counter1
// Prescalers): a free-running 10-bit counter shared by Timer0 and Timer1, NOT restarted when a timer's clock
// select is written, so a prescaled timer's first count comes 1..N cycles after its clock is enabled (the
// datasheet quotes "1 to N+1"; the extra cycle is the write's own cycle, which this model counts as the write).
// GTCCR.PSRSYNC restarts it; with GTCCR.TSM set the written PSR bit stays set and holds it in reset, which is
// the datasheet's way to start several timers in step. Timer2 has its own prescaler (§18.10, GTCCR.PSRASY).
//
// Convention: the prescaler counted 0 at cycle `origin` (power-on reset: cycle 0), so tap N ticks at cycles
// origin + k*N, k >= 1. Tap 1 (no prescaling) is the I/O clock itself and ticks every cycle, held or not.
#pragma once
#include <cstdint>
#include <optional>

namespace cnc::avr {

using Cycle = std::int64_t;  // ATmega328P clock cycles since reset (one cycle = 62.5 ns at 16 MHz)

class Prescaler {
public:
    // Cycle of the first tick of tap `divisor` strictly after `after`; none while held in reset.
    [[nodiscard]] std::optional<Cycle> first_tick_after(Cycle after, int divisor) const;
    // Number of ticks of tap `divisor` in (from, to] (from >= the last restart).
    [[nodiscard]] std::int64_t ticks_between(Cycle from, Cycle to, int divisor) const;

    void restart(Cycle c);  // PSR bit written with TSM clear: counts from 0 again at c
    void hold(Cycle c);     // PSR bit written with TSM set: held in reset from c
    void release(Cycle c);  // TSM cleared while held: counting restarts at c
    [[nodiscard]] bool held() const { return m_held; }
    // Changes at every restart, hold or release: lets the timers know their cached next event is stale.
    [[nodiscard]] std::uint64_t epoch() const { return m_epoch; }

private:
    Cycle m_origin = 0;
    bool m_held = false;
    std::uint64_t m_epoch = 0;
};

}  // namespace cnc::avr
