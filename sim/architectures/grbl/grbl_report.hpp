// The grbl section of the run report: the firmware's start-up message, the link at both ends, what the sender
// streamed (lines, the most bytes in flight, status queries) and every line grbl answered with an error.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "avr/avr_core.hpp"
#include "common/warning.hpp"
#include "host/grbl_sender.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim {

struct GrblFacts {
    const host::GrblSender& sender;
    const uart::Cp2102& cp2102;
    const avr::AvrCore& mcu;
    std::string firmware;
    std::string protocol;   // the grbl.protocol key's value
    double mcu_baud = 0.0;  // f_cpu / (8 (UBRR0 + 1)) with U2X0, as grbl sets it
};

// Framing errors at either end, and each line grbl answered with an error (lenient runs go on past them).
[[nodiscard]] std::vector<Warning> grbl_warnings(const GrblFacts& f);
[[nodiscard]] nlohmann::json grbl_details_json(const GrblFacts& f);
[[nodiscard]] std::string grbl_details_text(const GrblFacts& f);

}  // namespace cnc::sim
