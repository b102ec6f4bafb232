// Configuration of the AVR model (scenario section [avr]): the ATmega328P (seed 003) or the ATmega16 (seed 002).
#pragma once
#include <cstdint>
#include <string>

#include "avr/core/pin_map.hpp"
#include "common/clock_grid.hpp"

namespace cnc::avr {

struct AvrCoreConfig {
    std::string firmware_elf;        // an ELF or Intel HEX file for `mcu` (avr.firmware)
    std::string mcu = "atmega328p";  // or "atmega16" (core/mcu_map.hpp); an ELF whose .mmcu names another is refused
    std::uint32_t f_cpu_hz = 16'000'000;  // seed 003 §5.2.4: 16 MHz crystal (62.5 ns per cycle)
    // How this board's oscillator departs from f_cpu_hz (all zero: ideal). The firmware was built for f_cpu_hz;
    // every cycle, timer and USART bit takes the oscillator's real time.
    ClockDeviation clock;
    PinMap pins = default_pin_map();  // avr.pins
    // Temporal decoupling: the AVR runs at most this many cycles ahead of SystemC time before its recorded pin events
    // are replayed at their exact times. 160 cycles = 10 us: libsimavr in a SystemC thread ran an idle firmware (a
    // 10 kHz timer ISR) at 150 sim-MHz (9.4x real time) there, against 75 at 16 cycles and 175 at 1600. Outputs are
    // exact whatever the quantum; it only bounds how late the AVR sees an input (no input but RXD exists, and RXD is
    // exact: the AVR never runs past a pending frame's decision cycle). AvrCore also keeps it below the receiver's
    // decision delay minus 8 cycles (9.5 bit times: 2576 at UBRR0 = 16; 144 at the reset UBRR0 = 0).
    std::uint32_t quantum_cycles = 160;
    // UsartUnit::tx_log() / rx_log(): a record per byte, read only by the AVR model's tests, so a long job keeps
    // none unless asked (the counts are in UsartStats).
    bool keep_usart_logs = false;
    // Skip the iterations of polling loops that cannot change anything before the next event (loop_skipper.hpp):
    // the same outputs at the same cycles, faster. Off: every cycle is executed.
    bool fast_forward = true;
    std::string where = "avr.firmware";  // names the scenario key in bad-input messages
    std::string mcu_key;                 // the scenario key that chose `mcu` ("avr.mcu"), for messages; empty: none
};

}  // namespace cnc::avr
