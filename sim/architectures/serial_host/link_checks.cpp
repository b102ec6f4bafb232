#include "architectures/serial_host/link_checks.hpp"

#include <fmt/format.h>

#include "common/bad_input.hpp"
#include "uart/core/cp2102_baud.hpp"
#include "uart/core/rate_tolerance.hpp"

namespace cnc::sim {

LineEnd cp2102_end(const uart::Cp2102Config& link) {
    const uart::Cp2102Baud b = uart::cp2102_baud(link.requested_baud, link.ideal_baud);
    const std::string rate = link.ideal_baud
                                 ? fmt::format(FMT_STRING("(link.ideal_baud: exactly {:.0f} Bd)"), b.actual_bd)
                                 : fmt::format(FMT_STRING("(the CP2102 runs {:.2f} Bd)"), b.actual_bd);
    return {b.actual_bd, fmt::format(FMT_STRING("link.baud = {} {}"), link.requested_baud, rate)};
}

void check_line_rates(const std::string& where, const LineEnd& host, const LineEnd& controller) {
    const uart::FrameFormat frame = uart::kFormat8N1;  // every UART link of the project
    if (uart::rates_within_tolerance(host.baud, controller.baud, frame)) return;
    const double bits = uart::stop_sample_bits(frame);
    throw BadInput(
        where, fmt::format(FMT_STRING("baud mismatch: {} against {}: the host's line runs {:+.2f} % off the "
                                      "receiver's rate, and 8N1 works within +-{:.2f} % (the stop bit is "
                                      "sampled {:.1f} bits after the start edge: 0.5 / {:.1f} = {:.2f} % at "
                                      "most, halved for margin); give both ends one rate"),
                           host.setting, controller.setting, uart::rate_mismatch(host.baud, controller.baud) * 100.0,
                           uart::max_rate_mismatch(frame) * 100.0, bits, bits, 50.0 / bits));
}

std::optional<std::string> framing_failure(std::int64_t at_controller, const std::string& controller,
                                           std::int64_t at_host) {
    if (at_controller + at_host <= kFramingErrorsTolerated) return std::nullopt;
    return "the link garbles frames: " + std::to_string(at_controller) + " framing errors at the " + controller + ", " +
           std::to_string(at_host) + " at the CP2102 (a byte of the job was lost or changed, so the run is stopped)";
}

}  // namespace cnc::sim
