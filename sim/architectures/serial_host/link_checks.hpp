// The checks of a USB-UART link between a host and a controller, in one place so that every architecture with such
// a link says the same thing.
//
// Before the run: the host's line rate (the CP2102's actual rate for link.baud) against the controller's receiver
// (fpga.uart_baud; the firmware's UBRR0): beyond uart::max_rate_mismatch (2.63 % for 8N1, derived in
// models/uart/core/rate_tolerance.hpp) the scenario is refused, naming both settings, before anything is simulated.
//
// During the run: framing errors at either end. The simulated line has no noise and the rates have passed the
// check above, so no frame is received wrong on a working link: a framing error means a byte was lost or changed
// (a firmware that set another rate or frame format after the check, a line held low), and the job that runs is
// no longer the one that was sent. kFramingErrorsTolerated is therefore 0: the first one stops the run.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "uart/core/cp2102_config.hpp"

namespace cnc::sim {

inline constexpr std::int64_t kFramingErrorsTolerated = 0;

struct LineEnd {
    double baud = 0.0;
    std::string setting;  // what sets the rate, for the message: "link.baud = 57600 (the CP2102 runs 57 553.96 Bd)"
};

// The host's end: the CP2102's actual rate for link.baud (its 24 MHz divider, or exactly link.baud when ideal).
[[nodiscard]] LineEnd cp2102_end(const uart::Cp2102Config& link);

// Throws BadInput(where, ...) naming both ends when their rates are further apart than 8N1 allows.
void check_line_rates(const std::string& where, const LineEnd& host, const LineEnd& controller);

// The reason to stop the run, once the framing errors at either end exceed kFramingErrorsTolerated.
[[nodiscard]] std::optional<std::string> framing_failure(std::int64_t at_controller, const std::string& controller,
                                                         std::int64_t at_host);

}  // namespace cnc::sim
