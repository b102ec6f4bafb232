#include "architectures/avr_board/avr_board.hpp"

#include <optional>
#include <utility>

#include "architectures/serial_host/link_checks.hpp"

namespace cnc::sim {

avr::AvrCoreConfig board_config(const Scenario& s, const AvrBoardSettings& board, std::string firmware,
                                avr::PinMap pins) {
    avr::AvrCoreConfig cfg;
    cfg.firmware_elf = std::move(firmware);
    cfg.mcu = board.mcu;
    cfg.mcu_key = "avr.mcu";
    cfg.pins = avr::parse_pin_map(board.pins, s.file + ": avr.pins", std::move(pins), *avr::mcu_by_name(board.mcu));
    cfg.where = s.file + ": avr.firmware";
    cfg.quantum_cycles = board.quantum_cycles;
    cfg.fast_forward = board.fast_forward;
    cfg.clock = clock_deviation(board.clock, s.seed);
    return cfg;
}

std::optional<FirmwareUsart> check_firmware_rate(const Scenario& s, const uart::Cp2102Config& link,
                                                 const avr::AvrCoreConfig& cfg, const std::string& firmware_name) {
    std::optional<FirmwareUsart> usart = probe_firmware_usart(cfg);
    if (!usart) return usart;
    check_line_rates(s.file + ": link.baud, avr.firmware", cp2102_end(link),
                     {usart->baud, firmware_name + "'s USART" + usart->n + " at " + usart->text(cfg.f_cpu_hz)});
    return usart;
}

}  // namespace cnc::sim
