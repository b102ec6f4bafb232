// Scenario keys of the grbl architecture: [grbl] for the G-code sender (grbl.protocol, grbl.rx_buffer_bytes,
// grbl.status_interval_ms, grbl.settings), [avr] for the board and the firmware (avr_board/), and the link and host
// timing keys (serial_host/).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "architectures/architecture.hpp"
#include "architectures/avr_board/avr_board_settings.hpp"
#include "architectures/serial_host/serial_host_settings.hpp"
#include "common/units.hpp"
#include "host/core/grbl/grbl_stream.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct GrblSettings final : ArchSettings {
    SerialHostSettings serial;
    AvrBoardSettings board;
    host::grbl::Protocol protocol = host::grbl::Protocol::CharacterCounting;
    std::size_t rx_buffer_bytes = 128;
    TimePs status_interval_ps = 200 * kPsPerMs;
    std::vector<std::string> settings;  // grbl.settings, "$N=value"
    std::string settings_where;         // where grbl.settings was set, for its messages
    std::string firmware_where;         // where avr.firmware is (or would be) set
};

void read_grbl_settings(KeyReader& r, GrblSettings& settings, const std::filesystem::path& base);

}  // namespace cnc::sim
