#include "architectures/avr_board/board_link_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "architectures/serial_host/link_checks.hpp"

namespace cnc::sim {

nlohmann::json board_link_json(const uart::Cp2102& cp2102, const avr::AvrCore& mcu, double mcu_baud) {
    const uart::Cp2102Baud& baud = cp2102.baud();
    const avr::AvrCoreStats st = mcu.stats();
    return {{"requested_baud", baud.requested},
            {"line_baud", baud.actual_bd},
            {"line_baud_error_pct", baud.error_pct},
            {"mcu_baud", mcu_baud},
            {"mcu_vs_line_pct", (mcu_baud / baud.actual_bd - 1.0) * 100.0},
            {"bytes_to_mcu", cp2102.tx_log().size()},
            {"bytes_from_mcu", cp2102.rx_log().size()},
            {"framing_errors_at_mcu", st.usart.rx_framing_errors},
            {"framing_errors_at_host", cp2102.stats().framing_errors},
            {"frames_lost_at_mcu", st.usart.rx_lost_disabled + st.usart.rx_overruns}};
}

std::string board_link_text(const uart::Cp2102& cp2102, double mcu_baud) {
    const uart::Cp2102Baud& baud = cp2102.baud();
    return fmt::format(FMT_STRING("  line {:.2f} Bd ({:+.3f} % vs requested), MCU USART {:.1f} Bd: {:+.3f} % against "
                                  "the line\n"),
                       baud.actual_bd, baud.error_pct, mcu_baud, (mcu_baud / baud.actual_bd - 1.0) * 100.0);
}

std::vector<Warning> board_link_warnings(const uart::Cp2102& cp2102, const avr::AvrCore& mcu) {
    std::vector<Warning> w;
    const avr::AvrCoreStats st = mcu.stats();
    if (st.usart.rx_framing_errors > 0) {
        w.push_back(
            {"mcu_framing_errors", "", std::to_string(st.usart.rx_framing_errors) + " UART framing errors at the MCU"});
    }
    if (cp2102.stats().framing_errors > 0) {
        w.push_back({"cp2102_framing_errors", "",
                     std::to_string(cp2102.stats().framing_errors) + " UART framing errors at the CP2102"});
    }
    return w;
}

std::optional<std::string> board_link_failure(const avr::AvrCore& mcu, const uart::Cp2102& cp2102,
                                              const std::optional<std::string>& host_failure, bool line_faults) {
    if (!line_faults) {
        if (auto framing = framing_failure(mcu.stats().usart.rx_framing_errors, "MCU", cp2102.stats().framing_errors))
            return framing;
    }
    if (host_failure) return *host_failure + " (avr.firmware " + mcu.config().firmware_elf + ")";
    return std::nullopt;
}

std::string stopped_at(const std::string& why, TimePs stop_ps) {
    return why + fmt::format(FMT_STRING(" (run stopped at {:.3f} s of simulated time)"), ps_to_s(stop_ps));
}

}  // namespace cnc::sim
