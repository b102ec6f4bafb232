// The Arduino board's link with faults on its wires (faults.uart_*): the CP2102's TXD reaches RXD (PD0) through one
// faulty wire, TXD (PD1) reaches the CP2102's RXD through the other, each timed by its sender's bit clock
// (uart/faulty_line.hpp). At the end, the bytes each end framed are matched against those the other end sent
// (uart/core/frame_match.hpp), which needs every byte's record: a run with line faults keeps them (about 24 bytes a
// byte sent each way).
#pragma once
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>
#include <systemc>

#include "architectures/avr_board/board_wiring.hpp"
#include "architectures/avr_board/firmware_usart.hpp"
#include "avr/avr_core.hpp"
#include "scenario/fault_settings.hpp"
#include "uart/core/frame_match.hpp"
#include "uart/cp2102.hpp"
#include "uart/faulty_line.hpp"

namespace cnc::sim {

// What the faults did to each direction of the link.
struct BoardLineFaultResult {
    uart::FaultyLineStats to_mcu_line, from_mcu_line;  // frames hit on each wire
    uart::FrameMatch to_mcu, from_mcu;                 // what each receiver made of them
};

class BoardLineFaults {
public:
    // `cp2102_clock`, `mcu_clock`: the bit clocks of the two senders (the MCU's as its firmware sets USART0).
    BoardLineFaults(const FaultSettings& f, uart::BitClock cp2102_clock, uart::BitClock mcu_clock);

    // The two link wires through the faults (wire_board's link part).
    void wire(BoardWires& wires, uart::Cp2102& cp2102, avr::AvrCore& mcu);
    // The CP2102's logs before a reader drops them: the bytes it sent and those it framed, from where the last call
    // stopped; `unit(j)`: what byte j sent belongs to (a transfer, a G-code line), read now.
    void take_host_bytes(const uart::Cp2102& cp2102, const std::function<std::size_t(std::size_t)>& unit = {});
    // The units (as take_host_bytes numbered them) with a byte sent to the MCU that did not arrive as sent or with
    // a byte framed within it that was never sent; in order, each once.
    [[nodiscard]] std::vector<std::size_t> units_hit(const uart::FrameMatch& to_mcu) const;
    // The unit of the last byte the CP2102 sent (nullopt: none yet).
    [[nodiscard]] std::optional<std::size_t> last_unit_sent() const {
        return m_unit.empty() ? std::nullopt : std::optional(m_unit.back());
    }
    // After take_host_bytes has read the logs to the end.
    [[nodiscard]] BoardLineFaultResult result(const avr::AvrCore& mcu) const;

private:
    sc_core::sc_signal<bool> m_cp2102_txd{"cp2102_txd", true};  // before the wire to RXD
    sc_core::sc_signal<bool> m_mcu_txd{"mcu_txd", true};        // before the wire to the CP2102
    uart::FaultyLine m_to_mcu;
    uart::FaultyLine m_from_mcu;
    std::vector<uart::SentFrame> m_sent_to_mcu;
    std::vector<std::size_t> m_unit;
    std::vector<uart::ReceivedFrame> m_framed_at_host;
    std::size_t m_tx_read = 0;
    std::size_t m_rx_read = 0;
};

// The link's wires with the faults of `f`, if it asks for any (else null); the MCU's wire is timed by the firmware's
// USART0 (`usart`, from check_firmware_rate; the CP2102's rate if its receiver stayed off, when no byte passes).
[[nodiscard]] std::unique_ptr<BoardLineFaults> board_line_faults(const FaultSettings& f, const uart::Cp2102& cp2102,
                                                                 const std::optional<FirmwareUsart>& usart,
                                                                 std::int64_t f_cpu_hz);

// The report's `faults` section (the architecture adds its own fields) and its lines of text.
[[nodiscard]] nlohmann::json board_faults_json(const FaultSettings& f, const BoardLineFaultResult& r);
[[nodiscard]] std::string board_faults_text(const FaultSettings& f, const BoardLineFaultResult& r);

}  // namespace cnc::sim
