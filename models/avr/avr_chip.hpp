// The ATmega328P (or the ATmega16: the differences are in core/mcu_map.hpp and chip_io_atmega16.cpp) as
// libsimavr runs it, made to behave as the datasheet where libsimavr 1.6 does not, with its outputs time-stamped
// by clock cycle. No SystemC here: AvrCore (avr_core.hpp) is the SystemC shell.
//
// What runs where:
//   * libsimavr executes the instructions, the interrupt controller, the I/O ports and the other peripherals.
//   * Timer0, Timer1, Timer2 and USART0 (the ATmega16's USART) are NOT simavr's: their I/O registers are re-routed (avr->io[] read and write
//     handlers replaced after avr_init) to TimerUnit / UsartUnit, which are driven by one simavr cycle timer at their
//     next event. simavr 1.6's own timer model registers no timer when prescaler*(OCR+1) <= 1 (no compare match with
//     OCR = 0 at /1), drops a TCNT written while the clock is stopped when the clock starts (grbl's step pulse reset
//     relies on it), ignores the free-running prescaler and compare match blocking, mishandles an OCR written below
//     TCNT in CTC mode and reads a stopped timer's TCNT as 0; its USART sends a byte in 11 bit times (it always counts
//     a parity bit), clears UDRE0 for a whole byte time, latches the baud rate at the UBRR0L write, raises RXC0 one
//     such byte time after a byte is injected on UART_IRQ_INPUT, and has no line level at all. Replacing the units is
//     simpler and more exact than patching them.
//   * Interrupt flags still go through simavr's vectors (avr_raise_interrupt / avr_clear_interrupt). simavr only
//     queues an interrupt whose enable bit is set at the moment it is raised, so writes to TIMSKn and UCSR0B
//     re-raise flags that are already set, and RXC0 / UDRE0 (level interrupts on silicon) are re-raised after
//     the CPU takes their vector while the condition holds.
//   * Port writes are wrapped so that the model knows every output pin level, including the OCnx overrides.
//     Two more silicon details are restored there: SBI/CBI on PINx toggle only the addressed bit (simavr 1.6
//     writes the whole read-modify-written byte, toggling every other pin that reads 1), and SBI/CBI on TIFRn
//     clear only the addressed flag (datasheet "I/O Memory": on the ATmega328P SBI and CBI work on the one bit).
//
// Time convention: cycle n is the n-th clock since reset (n * 62.5 ns at 16 MHz). An instruction starting at
// cycle n does its I/O reads and writes at cycle n (simavr executes it whole), so a pin written by it changes at
// n * 62.5 ns; timer and USART events happen at their exact cycles, also inside multi-cycle instructions.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "avr/core/avr_config.hpp"
#include "avr/core/mcu_map.hpp"
#include "avr/core/prescaler.hpp"
#include "avr/core/timer_unit.hpp"
#include "avr/core/usart_unit.hpp"
#include "avr/loop_skipper.hpp"
#include "uart/core/line_receiver.hpp"

struct avr_t;
struct avr_int_vector_t;
struct avr_cycle_timer_slot_t;

namespace cnc::avr {

enum class ChipState { Running, Done, Crashed };

// Output lines: 0..6 = kPinSignals (step_x ... head), 7 = TXD.
inline constexpr int kTxdLine = 7;
inline constexpr int kLineCount = 8;

struct LineEvent {
    Cycle cycle = 0;
    int line = 0;
    bool level = false;
};

class AvrChip : private TimerSink, private UsartSink {
public:
    // Loads and checks the ELF; throws BadInput for a missing, non-AVR or wrong-MCU ELF.
    explicit AvrChip(const AvrCoreConfig& cfg);
    ~AvrChip() override;
    AvrChip(const AvrChip&) = delete;
    AvrChip& operator=(const AvrChip&) = delete;

    [[nodiscard]] Cycle cycle() const;
    // Runs until the cycle count reaches `limit` (instructions are atomic, so it may end a few cycles later, or
    // one cycle later when waking from sleep). After the firmware has stopped (cli; sleep) or crashed the CPU
    // executes nothing, but the timers and the USART keep running to `limit`, as on silicon.
    ChipState run_until(Cycle limit);
    [[nodiscard]] ChipState state() const { return m_state; }
    [[nodiscard]] std::optional<Cycle> stop_cycle() const { return m_stop_cycle; }

    // Output level changes with cycle <= upto, in time order, removed from the record.
    [[nodiscard]] std::vector<LineEvent> take_events(Cycle upto);
    [[nodiscard]] bool initial_level(int line) const { return m_initial[static_cast<std::size_t>(line)]; }

    // The receiver's bit clock and frame format now (for decoding the RXD line).
    [[nodiscard]] uart::BitClock rx_clock() const { return m_usart.bit_clock(m_clock.hz()); }
    [[nodiscard]] uart::FrameFormat rx_format() const { return m_usart.format(); }
    // A frame decoded from RXD, started at cycle `start`, decided at cycle `decision` (<= cycle()): the byte is
    // in the receive buffer from `decision` on.
    void deliver_rx(Cycle start, Cycle decision, const uart::RxFrame& frame);

    // Cycle of the next timer or USART event, if any is scheduled.
    [[nodiscard]] std::optional<Cycle> next_event() const;

    // An input pin driven from outside at the current cycle (after run_until): PINx reads it and, on the ATmega16,
    // INT0 (PD2) / INT1 (PD3) see the edge now (MCUCR ISCn1:0). The model's own edge detector, not simavr's:
    // simavr 1.6 raises INTFn for a low pin in the reset low-level mode and keeps re-entering the vector.
    void drive_input(const Pin& pin, bool level);

    // Called with the cycle of every port register write and compare output change, after it: a board model
    // that steps slower than the pins move (the HD44780's E pulse is 3 cycles long) reads the levels it needs
    // there with pin_level().
    void on_output_change(std::function<void(Cycle)> listener) { m_output_listener = std::move(listener); }

    // A pin's level now: an output's PORT bit or connected compare output, an input's external drive or pull-up.
    [[nodiscard]] bool pin_level(const Pin& p) const;
    // The EEPROM's content now (simavr's EEPROM; the ELF's .eeprom section is loaded at reset).
    [[nodiscard]] std::vector<std::uint8_t> eeprom() const;

    // What the polling-loop fast-forward skipped (all zero when AvrCoreConfig::fast_forward is off).
    [[nodiscard]] FastForwardStats fast_forward_stats() const {
        return m_skipper ? m_skipper->stats() : FastForwardStats{};
    }

    [[nodiscard]] const McuMap& mcu() const { return m_map; }
    [[nodiscard]] const UsartUnit& usart() const { return m_usart; }
    [[nodiscard]] const TimerUnit& timer(int n) const { return *m_timers.at(static_cast<std::size_t>(n)); }
    // The frequency the firmware was built for (F_CPU), and the oscillator's edges as they come.
    [[nodiscard]] std::int64_t f_cpu_hz() const { return m_f_cpu_hz; }
    [[nodiscard]] const ClockGrid& clock() const { return m_clock; }

private:
    struct Bridge;     // the C callbacks handed to libsimavr (avr_chip.cpp)
    struct PortHooks;  // simavr's own PINx/DDRx/PORTx handlers, called from the wrappers
    enum class Timer1Reg { Tcnt, Icr, OcrA, OcrB };

    [[nodiscard]] static const McuMap& checked_mcu(const AvrCoreConfig& cfg);

    // I/O bus (chip_io.cpp), called from the simavr read/write hooks at the current cycle.
    void io_write(std::uint16_t addr, std::uint8_t v);
    [[nodiscard]] std::uint8_t io_read(std::uint16_t addr);
    void io_write_atmega16(std::uint16_t addr, std::uint8_t v);  // chip_io_atmega16.cpp
    // The timer registers both MCUs share (McuMap::timer_regs): false / nullopt for any other address.
    bool write_shared_timer_reg(std::uint16_t addr, std::uint8_t v);
    [[nodiscard]] std::optional<std::uint8_t> read_shared_timer_reg(std::uint16_t addr);
    // The USART's registers (McuMap::usart, chip_io_usart.cpp): false / nullopt for any other address.
    bool write_usart_reg(std::uint16_t addr, std::uint8_t v);
    [[nodiscard]] std::optional<std::uint8_t> read_usart_reg(std::uint16_t addr);
    void install_atmega16_hooks(const std::function<void(std::uint16_t)>& take_write,
                                const std::function<void(std::uint16_t)>& take_read);
    // §16.3 (328P) / "Accessing 16-bit Registers" (ATmega16): a low byte read latches the high byte in TEMP; a
    // low byte write moves TEMP:low into the register.
    [[nodiscard]] std::uint8_t latch_high(std::uint16_t v);
    void write_timer1_low(Timer1Reg r, std::uint16_t low_addr, std::uint8_t low);
    // Scheduler: processes every timer/USART event at cycles <= c; returns the next event cycle.
    std::optional<Cycle> process_events(Cycle c);
    void vector_cleared(avr_int_vector_t* v);
    void vector_entered(avr_int_vector_t* v);

    void timer_flag(char timer, TimerFlag flag, Cycle c) override;
    void timer_output(char timer, Cycle c) override;
    void usart_flags(Cycle c) override;
    void usart_txd(Cycle c, bool level) override;

    void install_hooks();
    [[nodiscard]] std::vector<std::uint16_t> pin_registers() const;
    void run_instructions(Cycle limit);
    [[nodiscard]] const avr_cycle_timer_slot_t* other_cycle_timer() const;
    // Whether a cycle timer other than the scheduler's and the run_until boundary's is due now.
    [[nodiscard]] bool other_timer_due() const;
    [[nodiscard]] bool quiet_flag(char timer, TimerFlag flag) const;
    [[nodiscard]] Cycle quiet_until() const;
    void disturb() {
        if (m_skipper) m_skipper->disturb();
    }
    void disconnect_external_interrupts();
    void reschedule();
    void update_quiet_flags();
    [[nodiscard]] Cycle now() const;
    // Raise a vector (or, for a level interrupt, follow its flag) at cycle c: the flag's cycle, which times a
    // wake-up from sleep.
    void raise(int vector_number, Cycle c);
    void raise_vector(avr_int_vector_t* v, Cycle c);
    void sync_level_vector(int vector_number, bool flag, Cycle c);
    void port_write(std::uint16_t addr, std::uint8_t v);
    [[nodiscard]] std::uint8_t port_read(std::uint16_t pin_addr);
    // A pin with its port's registers and the compare output that may drive it, found once: the levels of every
    // line are asked at each port write and compare output change.
    struct PinSource {
        std::size_t port = 0;  // McuMap::ports index
        std::uint16_t ddr = 0;
        std::uint16_t port_reg = 0;
        int bit = 0;
        const TimerUnit* oc_timer = nullptr;  // the compare output on this pin, if the MCU has one
        Channel oc_channel = Channel::A;
    };
    [[nodiscard]] PinSource pin_source(const Pin& p) const;
    [[nodiscard]] bool level_of(const PinSource& s) const;
    void update_lines(Cycle c);
    void record(Cycle c, int line, bool level);
    [[nodiscard]] int timer_vector(int timer, TimerFlag flag) const;
    [[nodiscard]] int flag_bit_vector(std::uint16_t mask_or_flag_addr, int bit) const;
    [[nodiscard]] std::optional<std::size_t> port_reg_index(std::uint16_t addr) const;
    [[nodiscard]] std::size_t port_index(char port) const;
    // ATmega16 INT0/INT1 (chip_io_atmega16.cpp): the edge detector on PD2/PD3, and the low-level mode's re-raise.
    void external_interrupt_edge(const Pin& pin, bool was, bool now_level);
    void external_interrupt_entered(int vector_number);
    void write_gicr(std::uint8_t v);
    void write_gifr(std::uint8_t v);
    void write_timer_flags(std::uint16_t addr, std::uint8_t v);
    void write_timsk(std::uint16_t addr, std::uint8_t v);
    void write_gtccr(std::uint8_t v);
    [[nodiscard]] std::optional<int> single_bit_instruction(std::uint16_t addr, bool* set) const;

    const McuMap& m_map;
    const std::int64_t m_f_cpu_hz;
    const ClockGrid m_clock;
    std::array<PinSource, kPinSignals.size()> m_line_sources{};  // kPinSignals order
    Prescaler m_prescaler01;                            // Timer0 and Timer1 (§17)
    Prescaler m_prescaler2;                             // Timer2 (§18.10)
    std::array<std::unique_ptr<TimerUnit>, 3> m_timers;
    UsartUnit m_usart;
    std::uint8_t m_temp16 = 0;  // Timer1's TEMP register for 16-bit accesses (§16.3)
    std::optional<Cycle> m_shared_read_cycle;  // the ATmega16's last read of UBRRH/UCSRC
    avr_t* m_avr = nullptr;
    std::unique_ptr<PortHooks> m_port_hooks;
    bool m_quiet_flags_stale = false;  // a timer flag raised, TIFRn or TIMSKn written since the timers were told
    bool m_reti_ran = false;           // in the instruction just run: an interrupt vector returned
    bool m_after_reti = false;  // a RETI ran: the interrupted loop may be a proven one once the next instruction ran
    std::unique_ptr<LoopSkipper> m_skipper;         // null: fast-forward off
    Cycle m_run_limit = 0;                          // of the run_until running
    std::array<avr_int_vector_t*, 26> m_vectors{};  // simavr's interrupt vectors by number (0 = none)
    ChipState m_state = ChipState::Running;
    std::optional<Cycle> m_stop_cycle;
    std::optional<Cycle> m_wake_flag_cycle;  // the flag that woke the CPU from sleep, until its vector runs
    bool m_in_scheduler = false;
    std::optional<Cycle> m_scheduled;  // the cycle the scheduler's simavr cycle timer is registered at
    std::array<bool, kLineCount> m_initial{};
    std::array<bool, kLineCount> m_level{};
    std::vector<LineEvent> m_events;
    std::function<void(Cycle)> m_output_listener;
    // Externally driven input pins, [port index][bit]: -1 undriven, else the level.
    std::array<std::array<std::int8_t, 8>, 4> m_inputs{{{-1, -1, -1, -1, -1, -1, -1, -1},
                                                        {-1, -1, -1, -1, -1, -1, -1, -1},
                                                        {-1, -1, -1, -1, -1, -1, -1, -1},
                                                        {-1, -1, -1, -1, -1, -1, -1, -1}}};
};

}  // namespace cnc::avr
