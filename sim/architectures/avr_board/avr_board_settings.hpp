// The Arduino board with its ATmega328P that two architectures share (seed 003's firmware runs on it, and grbl or
// a user's firmware on grbl's pins), or an ATmega16 in its place: the keys [avr] mcu, firmware, pins and
// quantum_cycles, and its 16 MHz resonator (clock.*, avr.clock_tolerance_ppm, avr.clock_jitter_rms_ps), read by one
// reader.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

#include "architectures/oscillator/oscillator_settings.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct AvrBoardSettings {
    std::string mcu = "atmega328p";  // avr.mcu: the MCU on the board, "atmega328p" or "atmega16"
    std::string firmware;  // avr.firmware resolved against the scenario's folder; empty: the architecture's default
    std::string pins;      // avr.pins, "signal=pin, ..."; empty: the architecture's map
    // avr.quantum_cycles. 1600 (100 us), not AvrCoreConfig's 160: the outputs are exact at any value and the only
    // input, RXD, is decoded exactly, so a longer quantum costs nothing here; it runs the square job 25 % faster.
    std::uint32_t quantum_cycles = 1600;
    OscillatorSettings clock;  // the Arduino's resonator
    bool fast_forward = true;  // avr.fast_forward
};

// An AVR's fast-forward key (avr.fast_forward, lathe.fast_forward): AvrCoreConfig::fast_forward.
[[nodiscard]] bool read_fast_forward(KeyReader& r, const std::string& key);

void read_avr_board_settings(KeyReader& r, AvrBoardSettings& s, const std::filesystem::path& base);

}  // namespace cnc::sim
