// What the architectures on the Arduino board share at run time: the MCU's configuration from the [avr] keys,
// and the check of its firmware's USART rate against the CP2102's before anything is simulated.
#pragma once
#include <optional>
#include <string>

#include "architectures/avr_board/avr_board_settings.hpp"
#include "architectures/avr_board/firmware_usart.hpp"
#include "avr/core/avr_config.hpp"
#include "scenario/scenario.hpp"
#include "uart/core/cp2102_config.hpp"

namespace cnc::sim {

// `firmware`: the file to run; `pins`: the architecture's map that avr.pins overrides. BadInput for a bad avr.pins
// (a pin avr.mcu lacks too).
[[nodiscard]] avr::AvrCoreConfig board_config(const Scenario& s, const AvrBoardSettings& board, std::string firmware,
                                              avr::PinMap pins);

// The firmware's USART0 (read off the firmware booted alone) against the CP2102's rate for link.baud: BadInput
// naming both when 8N1 cannot bridge them. `firmware_name`: how the message names the firmware. Returns the
// firmware's USART0 (nullopt: its receiver stayed off).
std::optional<FirmwareUsart> check_firmware_rate(const Scenario& s, const uart::Cp2102Config& link,
                                                 const avr::AvrCoreConfig& cfg, const std::string& firmware_name);

}  // namespace cnc::sim
