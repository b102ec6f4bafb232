// The USB-UART link of the Arduino board as the report shows it for every architecture on it: the CP2102's rate
// against the MCU's USART, the bytes each way, framing errors and lost frames at either end.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "avr/avr_core.hpp"
#include "common/warning.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim {

// `mcu_baud`: f_cpu / (16 (UBRR0 + 1)) (or / 8 with U2X0) as the firmware set it.
[[nodiscard]] nlohmann::json board_link_json(const uart::Cp2102& cp2102, const avr::AvrCore& mcu, double mcu_baud);
// "  line 115 200.00 Bd (+0.000 % vs requested), MCU USART 117 647.1 Bd: +2.124 % against the line\n"
[[nodiscard]] std::string board_link_text(const uart::Cp2102& cp2102, double mcu_baud);
// Framing errors at either end.
[[nodiscard]] std::vector<Warning> board_link_warnings(const uart::Cp2102& cp2102, const avr::AvrCore& mcu);
// Why the link stops the run, once it is clear: frames garbled at either end (serial_host/link_checks.hpp: a rate
// the check let through; not on wires with faults, where they are the faults' own), or the host program's own
// reason (`host_failure`), with the firmware it met.
[[nodiscard]] std::optional<std::string> board_link_failure(const avr::AvrCore& mcu, const uart::Cp2102& cp2102,
                                                            const std::optional<std::string>& host_failure,
                                                            bool line_faults);
// "why (run stopped at 1.234 s of simulated time)"
[[nodiscard]] std::string stopped_at(const std::string& why, TimePs stop_ps);

}  // namespace cnc::sim
