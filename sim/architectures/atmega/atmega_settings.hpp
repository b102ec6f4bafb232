// Scenario keys of the atmega architecture (seed 003), read into one struct by read_atmega_settings(): the host's
// link and program (serial_host: [link] and host.settle_s .. host.on_timeout), [avr] for the simulated ATmega328P
// (firmware, pins), [atmega] for the seed 003 PC program and firmware build.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

#include "architectures/architecture.hpp"
#include "architectures/avr_board/avr_board_settings.hpp"
#include "architectures/serial_host/serial_host_settings.hpp"
#include "host/core/cad2g/plan.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct AtmegaSettings final : ArchSettings {
    SerialHostSettings serial;
    // board.firmware empty: the built seed 003 ELF of avr.variant (pc.variant); a firmware named with a variant runs
    // with that variant's protocol and pin map. board.pins empty: the pin map of avr.variant (seed 003's, or
    // timer1-y's).
    AvrBoardSettings board;
    int g01_timer2_prescaler = 1024;  // which built seed 003 ELF: 1024, or 256 (App. A3's CS = 110 as listed)
    host::cad2g::PcOptions pc;        // with avr.variant
    // link.baud set by the scenario: otherwise the PC program asks for 57600 (seed 003 §5.3.2 CBR_57600), not the
    // Cp2102Config default of seed 000.
    bool link_baud_set = false;
};

void read_atmega_settings(KeyReader& r, AtmegaSettings& settings, const std::filesystem::path& base);

}  // namespace cnc::sim
