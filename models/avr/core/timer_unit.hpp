// One ATmega328P Timer/Counter (Timer0, Timer1 or Timer2) as the datasheet describes it, cycle-exact and
// event-driven: the counter value is derived from the tick count, and the unit is only stepped at ticks where
// something happens (a compare match, TOP, BOTTOM, a wrap), never once per timer clock.
//
// Tick rules (datasheet §15.7 / §16.9 / §18.7 timing diagrams; the same for every mode):
//   * The counter changes at each tick of its clock (prescaler tap N, see Prescaler).
//   * A compare match exists while TCNTn == OCRnx; it sets OCFnx and acts on OCnx "at the next timer clock
//     cycle", i.e. at the tick that moves the counter off the matching value. So in CTC mode with OCRnA = R the
//     counter reads R for one full timer clock and the tick that clears it to 0 also sets OCFnA and toggles
//     OCnA: a toggle every N*(R+1) cycles, and with R = 0 a toggle at every tick.
//   * TOVn is set at the tick that leaves MAX (Normal, CTC) or TOP (fast PWM), or that leaves BOTTOM (phase
//     correct and phase and frequency correct). ICF1 is set at the tick that leaves TOP when ICR1 is TOP.
//   * A CPU write to TCNTn blocks the compare matches of the next timer clock (datasheet §15.5.2 "Compare Match
//     Blocking by TCNT0 Write"), even while the timer is stopped; the CTC clear at TOP still happens (decision:
//     the datasheet only says the match is blocked).
//   * A written TCNTn is kept while the clock is stopped and counting resumes from it when a clock is selected.
//   * OCRnx are double buffered in the PWM modes (updated at BOTTOM in fast PWM and phase and frequency correct,
//     at TOP in phase correct); in Normal and CTC modes a write takes effect at once, so an OCRnA below the
//     current count in CTC mode makes the counter run to MAX and wrap (the datasheet's warning).
//   * FOCnx (non-PWM modes) applies the compare output action at once, without a flag or a clear.
//   * Fast PWM: the BOTTOM action (set or clear OCnx) comes after the compare action of the same tick, so
//     OCRnx = TOP gives a constant level and OCRnx = 0 a one-timer-clock spike (datasheet §15.7.3).
// Decisions where the datasheet is silent: the OCR buffers are copied at the tick that wraps to BOTTOM (fast
// PWM), that leaves BOTTOM (phase and frequency correct) or that leaves TOP (phase correct); with TOP = 0 a
// dual-slope counter stays at 0 and every tick is both TOP and BOTTOM; a dual-slope counter above a lowered
// TOP counts up to MAX and wraps to 0 without setting TOVn.
// Register accesses at cycle c see every tick at cycles <= c (the instruction runs after the ticks of its cycle).
// Not modelled: external clock sources (CS = 110/111 on Timer0/1), Timer2's asynchronous 32 kHz mode, input
// capture on ICP1, the PRR power-reduction bits, and phase correct's OCnx symmetry transitions at BOTTOM.
#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "avr/core/prescaler.hpp"
#include "avr/core/timer_mode.hpp"

namespace cnc::avr {

enum class TimerFlag { Overflow, CompareA, CompareB, Capture };
enum class Channel { A = 0, B = 1 };

struct TimerSpec {
    char name = '0';
    bool sixteen_bit = false;
    std::array<int, 8> divisors{};  // clock select CSn2:0 -> prescaler tap; 0 = stopped, -1 = external pin
};

// Datasheet Table 15-9 (Timer0) / 16-5 (Timer1): /1 /8 /64 /256 /1024, CS = 110/111 = external pin T0/T1.
inline constexpr TimerSpec kTimer0{'0', false, {0, 1, 8, 64, 256, 1024, -1, -1}};
inline constexpr TimerSpec kTimer1{'1', true, {0, 1, 8, 64, 256, 1024, -1, -1}};
// Table 18-9 (Timer2): /1 /8 /32 /64 /128 /256 /1024.
inline constexpr TimerSpec kTimer2{'2', false, {0, 1, 8, 32, 64, 128, 256, 1024}};

class TimerSink {
public:
    virtual ~TimerSink() = default;
    virtual void timer_flag(char timer, TimerFlag flag, Cycle c) = 0;
    // The OCnA/OCnB level or connection may have changed at cycle c.
    virtual void timer_output(char timer, Cycle c) = 0;
};

class TimerUnit {
public:
    TimerUnit(const TimerSpec& spec, const Prescaler& prescaler, TimerSink& sink);
    // This unit in its state now, reporting to `sink`: a probe that can be advanced to see what comes next.
    [[nodiscard]] TimerUnit copy_for(TimerSink& sink) const;

    // Register writes and reads at cycle c (ticks at cycles <= c are applied first). TCCRnB carries FOCnA/B for
    // Timer0/2; Timer1's are in TCCR1C. 16-bit values are whole registers (the TEMP byte protocol is the bus's).
    void write_tccra(Cycle c, std::uint8_t v);
    void write_tccrb(Cycle c, std::uint8_t v);
    void write_tccrc(Cycle c, std::uint8_t v);
    void write_tcnt(Cycle c, std::uint16_t v);
    void write_ocr(Cycle c, Channel ch, std::uint16_t v);
    void write_icr(Cycle c, std::uint16_t v);
    [[nodiscard]] std::uint16_t read_tcnt(Cycle c);
    [[nodiscard]] std::uint8_t tccra() const { return m_tccra; }
    [[nodiscard]] std::uint8_t tccrb() const { return m_tccrb; }
    [[nodiscard]] std::uint16_t ocr(Channel ch) const { return m_ocr_buffer[idx(ch)]; }  // the CPU sees the buffer
    [[nodiscard]] std::uint16_t icr() const { return m_icr; }

    // Applies every tick at cycles <= c.
    void advance_to(Cycle c);
    // The flags (bit 1 << TimerFlag) whose raising changes nothing now: set already, their interrupt disabled (the
    // owner knows). While the counter runs 0..TOP in a single-slope mode, a tick whose every effect is raising such
    // flags is not stepped or reported: the count is advanced over it in closed form, and next_event() is the next
    // tick that does something (none if no tick does). A change takes effect after cycle c.
    void set_quiet_flags(Cycle c, std::uint8_t mask);
    // Cycle of the next tick that does something; none while the clock is stopped. Depends on the shared
    // prescaler: advance the unit to c before the prescaler is restarted at c, and ask again afterwards.
    [[nodiscard]] std::optional<Cycle> next_event() const;

    [[nodiscard]] bool output_connected(Channel ch) const { return output(ch).connected; }
    [[nodiscard]] bool output_level(Channel ch) const { return m_oc[idx(ch)]; }
    [[nodiscard]] const TimerSpec& spec() const { return m_spec; }
    [[nodiscard]] const TimerMode& mode() const { return m_mode; }
    [[nodiscard]] int divisor() const { return m_spec.divisors[m_tccrb & 7U]; }
    [[nodiscard]] std::uint64_t event_ticks() const { return m_event_ticks; }  // stepped ticks (cost metric)

private:
    static constexpr std::size_t idx(Channel ch) { return static_cast<std::size_t>(ch); }
    [[nodiscard]] std::uint16_t max() const { return m_spec.sixteen_bit ? 0xFFFF : 0xFF; }
    [[nodiscard]] std::uint16_t top() const;
    [[nodiscard]] CompareOutput output(Channel ch) const;
    [[nodiscard]] TimerMode decode_mode() const;  // from the WGM bits of TCCRnA and TCCRnB
    [[nodiscard]] std::optional<std::int64_t> distance_to(std::uint16_t x) const;
    [[nodiscard]] std::optional<std::int64_t> ticks_to_event() const;
    [[nodiscard]] bool quiet(TimerFlag f) const { return ((m_quiet_flags >> static_cast<unsigned>(f)) & 1U) != 0; }
    // Single slope, counting 0..TOP (not above TOP, where it runs on to MAX).
    [[nodiscard]] bool counts_to_top(const TimerMode& m) const;
    [[nodiscard]] std::optional<Cycle> tick_cycle(std::int64_t k) const;
    [[nodiscard]] std::int64_t ticks_until(Cycle c) const;
    void advance_quietly(std::int64_t ticks);
    void step(Cycle c);
    void apply(Channel ch, OcAction a, Cycle c);
    [[nodiscard]] bool any_output_connected() const;
    // After a TCCRnA/B write: the mode decoded again, and the sink told if an output was or is connected.
    void mode_changed(Cycle c, bool was_connected);
    void changed() { m_next_valid = false; }

    const TimerSpec m_spec;
    const Prescaler& m_prescaler;
    TimerSink* m_sink;
    std::uint8_t m_tccra = 0;
    std::uint8_t m_tccrb = 0;  // FOC bits never stored: they read as zero
    TimerMode m_mode;          // decode_mode(), kept with the registers
    std::uint16_t m_tcnt = 0;
    bool m_counting_up = true;  // dual-slope direction
    bool m_block_next_match = false;
    std::array<std::uint16_t, 2> m_ocr{};         // active compare values
    std::array<std::uint16_t, 2> m_ocr_buffer{};  // what the CPU wrote (= active outside PWM modes)
    std::uint16_t m_icr = 0;
    std::array<bool, 2> m_oc{};  // OCnA / OCnB output registers (reset: 0)
    Cycle m_last = 0;            // ticks at cycles <= m_last are applied
    std::uint8_t m_quiet_flags = 0;
    std::uint64_t m_event_ticks = 0;
    // next_event() is asked after every instruction's I/O: it is cached until the state or the prescaler changes
    // (advancing over quiet ticks does not move the next event).
    mutable bool m_next_valid = false;
    mutable std::uint64_t m_next_epoch = 0;
    mutable std::optional<Cycle> m_next;
};

}  // namespace cnc::avr
