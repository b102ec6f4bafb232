// AvrCore: an ATmega328P running any firmware ELF (libsimavr, made silicon-exact for Timer0/1/2 and USART0 by
// AvrChip), as a SystemC module. No wall-clock pacing: it runs as fast as the host allows.
//
// Outputs. Each signal of the pin map (avr.pins) is an sc_out<bool> port, and so is TXD; every change is written
// at exactly its cycle's clock edge (cycle * 62.5 ns at 16 MHz on an ideal clock; AvrCoreConfig::clock moves the
// edges as the board's oscillator does). The AVR runs ahead of SystemC time by at most a quantum of cycles
// (AvrCoreConfig::quantum_cycles: temporal decoupling), then its recorded output changes are
// replayed at their exact times and the thread waits until SystemC time equals the AVR's time again.
// A port pin's level is its OCnx output while a timer's COM bits connect it and its DDR bit is set, else its
// PORT bit (an input pin is pulled up by PORT = 1, or floats and is pulled low by the DRV8825's pull-downs).
// At reset every pin is an input with PORT = 0: low. TXD idles high.
//
// Input. RXD (USART0, from the CP2102's TXD) is decoded as the AVR's receiver does it, at the AVR's own bit
// clock (UBRR0, U2X0): sampled in the middle of each bit from the start edge (cnc::uart::receive_frame; the
// silicon majority-votes 3 of 16 samples per bit around the middle, which gives the same result on a clean
// line). A sender off the AVR's baud rate drifts a little more each bit: one about 5.6 % or more slower has its
// stop bit sampled inside its last data bit (FE0 set when that bit is 0, counted as a framing error); one as
// much faster has its bits sampled one late, with no FE0 (the stop bit sample finds the idle line). The CP2102's
// 57 553.96 Bd against the AVR's 58 823.5 Bd (2.2 %) is received correctly.
// RXC0 rises at the decision (the middle of the stop bit) at the exact cycle: when a start bit is seen the AVR is
// not run past that frame's decision cycle until the frame has been decoded, and the quantum is capped below a
// frame's decision delay so that a start bit can never be seen too late. Frames starting while RXEN0 = 0 are
// lost; they are counted as the receiver would frame them at its current bit clock (before the firmware sets
// UBRR0 that clock is the reset UBRR0 = 0, 1 Mbd, and one slow byte may count as several).
//
// Not modelled: other inputs (the seed's limit switches read as open), and TXD while TXEN0 = 0 (the real pin
// then follows PORTD1; here it stays high).
//
// Every port must be bound. When the firmware stops (cli; sleep) or crashes, stopped_event() fires; the timers
// and the USART keep running, as on silicon, so the thread never runs out of work while a timer runs: bound
// sc_start() or call sc_stop().
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <systemc>

#include "avr/avr_chip.hpp"
#include "avr/core/avr_config.hpp"
#include "common/edge_log.hpp"
#include "common/units.hpp"
#include "uart/core/uart_frame.hpp"

namespace cnc::avr {

struct AvrCoreStats {
    std::int64_t cycles = 0;
    UsartStats usart;
    std::int64_t rx_false_starts = 0;    // start bits high again at their middle (glitches): no frame
    std::int64_t rx_late_decisions = 0;  // frames decoded after the AVR had passed their decision cycle (0)
};

class AvrCore : public sc_core::sc_module {
public:
    sc_core::sc_out<bool> step_x;
    sc_core::sc_out<bool> dir_x;
    sc_core::sc_out<bool> en_x;  // active low at the DRV8825 (seed 003 §5.2.5)
    sc_core::sc_out<bool> step_y;
    sc_core::sc_out<bool> dir_y;
    sc_core::sc_out<bool> en_y;
    sc_core::sc_out<bool> head;
    sc_core::sc_out<bool> txd;  // USART0 TXD (PD1)
    sc_core::sc_in<bool> rxd;   // USART0 RXD (PD0)

    // Throws BadInput for a missing, non-AVR or wrong-MCU firmware (see AvrChip).
    AvrCore(const sc_core::sc_module_name& name, const AvrCoreConfig& cfg);

    [[nodiscard]] const AvrChip& chip() const { return *m_chip; }
    [[nodiscard]] Cycle cycle() const { return m_chip->cycle(); }
    [[nodiscard]] TimePs cycle_ps(Cycle c) const { return m_chip->clock().at(c); }
    [[nodiscard]] AvrCoreStats stats() const;
    [[nodiscard]] bool stopped() const { return m_chip->state() != ChipState::Running; }
    [[nodiscard]] const sc_core::sc_event& stopped_event() const { return m_stopped_ev; }
    [[nodiscard]] const AvrCoreConfig& config() const { return m_cfg; }

private:
    struct PendingFrame {
        TimePs t_fall_ps = 0;
        uart::BitClock clk;
        uart::FrameFormat fmt;
        TimePs t_decision_ps = 0;
        Cycle start_cycle = 0;
        Cycle decision_cycle = 0;
    };

    void run();     // SC_THREAD: the temporal-decoupling loop
    void on_rxd();  // SC_METHOD: RXD transitions
    void start_frame(TimePs t_fall_ps);
    void decide_frame();
    void replay(Cycle upto);
    [[nodiscard]] Cycle replay_bound(Cycle c) const;
    void wait_until_ps(TimePs t_ps);
    [[nodiscard]] Cycle first_cycle_at_or_after(TimePs t_ps) const;
    [[nodiscard]] Cycle run_ahead_limit() const;

    const AvrCoreConfig m_cfg;
    std::unique_ptr<AvrChip> m_chip;
    std::array<sc_core::sc_out<bool>*, kLineCount> m_lines{};
    sc_core::sc_event m_stopped_ev;
    bool m_stop_notified = false;
    bool m_rx_started = false;
    bool m_rx_level = true;
    EdgeLog m_rx_line{"rxd", true, {}};
    std::unique_ptr<PendingFrame> m_rx;
    std::int64_t m_rx_false_starts = 0;
    std::int64_t m_rx_late = 0;
};

}  // namespace cnc::avr
