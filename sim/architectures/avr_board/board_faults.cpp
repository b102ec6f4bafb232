#include "architectures/avr_board/board_faults.hpp"

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "architectures/serial_host/host_faults.hpp"
#include "common/clock_grid.hpp"
#include "uart/core/cp2102_baud.hpp"

namespace cnc::sim {

namespace {

// A receiver starts its frame at its first clock edge at or after the fall: within one period of its clock, and the
// edge's jitter (cut at kJitterCutSigmas).
TimePs start_tolerance_ps(const ClockGrid& receiver) {
    return cycles_to_ps(1, receiver.hz()) + static_cast<TimePs>(std::ceil(kJitterCutSigmas * receiver.jitter_rms_ps()));
}

nlohmann::json direction_json(const uart::FaultyLineStats& line, const uart::FrameMatch& m) {
    nlohmann::json j = faulty_line_json(line);
    j.update({{"bytes_as_sent", m.as_sent},
              {"bytes_wrong", m.wrong},
              {"bytes_lost", m.lost},
              {"bytes_extra", m.extra_frames},
              {"framing_errors_flagged", m.framing_flagged}});
    return j;
}

std::string direction_text(const char* what, const uart::FaultyLineStats& line, const uart::FrameMatch& m) {
    return fmt::format(FMT_STRING("  {}: {} of {} frames hit ({} lost, {} bits inverted); bytes: {} as sent, {} wrong, "
                                  "{} lost, {} framed from nothing, {} with the framing-error flag\n"),
                       what, line.frames_hit, line.frames, line.frames_lost, line.bits_inverted, m.as_sent, m.wrong,
                       m.lost, m.extra_frames, m.framing_flagged);
}

}  // namespace

BoardLineFaults::BoardLineFaults(const FaultSettings& f, uart::BitClock cp2102_clock, uart::BitClock mcu_clock)
    : m_to_mcu("to_mcu_line", f.uart, f.seed, 0, cp2102_clock),
      m_from_mcu("from_mcu_line", f.uart, f.seed, 1, mcu_clock) {}

void BoardLineFaults::wire(BoardWires& wires, uart::Cp2102& cp2102, avr::AvrCore& mcu) {
    cp2102.txd(m_cp2102_txd);
    m_to_mcu.in(m_cp2102_txd);
    m_to_mcu.out(wires.uart_rx);
    mcu.txd(m_mcu_txd);
    m_from_mcu.in(m_mcu_txd);
    m_from_mcu.out(wires.uart_tx);
}

void BoardLineFaults::take_host_bytes(const uart::Cp2102& cp2102, const std::function<std::size_t(std::size_t)>& unit) {
    for (std::size_t j = std::max(m_tx_read, cp2102.tx_log().first()); j < cp2102.tx_log().size(); ++j) {
        const uart::Cp2102::TxByte& b = cp2102.tx_log()[j];
        m_sent_to_mcu.push_back({b.t_start_bit_ps, b.t_stop_end_ps, b.byte});
        m_unit.push_back(unit ? unit(j) : j);
    }
    m_tx_read = cp2102.tx_log().size();
    for (std::size_t j = std::max(m_rx_read, cp2102.rx_log().first()); j < cp2102.rx_log().size(); ++j) {
        const uart::Cp2102::RxByte& b = cp2102.rx_log()[j];
        m_framed_at_host.push_back({b.t_start_bit_ps, b.byte, b.framing_error});
    }
    m_rx_read = cp2102.rx_log().size();
}

std::vector<std::size_t> BoardLineFaults::units_hit(const uart::FrameMatch& to_mcu) const {
    std::vector<std::size_t> hit;
    for (std::size_t j = 0; j < to_mcu.fate.size(); ++j) {
        if (to_mcu.fate[j] == uart::FrameFate::AsSent && to_mcu.extra[j] == 0) continue;
        if (hit.empty() || hit.back() != m_unit[j]) hit.push_back(m_unit[j]);
    }
    return hit;
}

BoardLineFaultResult BoardLineFaults::result(const avr::AvrCore& mcu) const {
    const avr::UsartUnit& usart = mcu.chip().usart();
    // The bytes the firmware can read: those that reached the receive buffer.
    std::vector<uart::ReceivedFrame> framed_at_mcu;
    for (const avr::UsartRxRecord& r : usart.rx_log()) {
        if (!r.stored) continue;
        framed_at_mcu.push_back({mcu.cycle_ps(r.start_cycle), r.byte, r.status == uart::RxStatus::FramingError});
    }
    std::vector<uart::SentFrame> sent_by_mcu;
    for (const avr::UsartTxRecord& t : usart.tx_log()) {
        sent_by_mcu.push_back({mcu.cycle_ps(t.start_cycle), mcu.cycle_ps(t.end_cycle), t.byte});
    }
    return {m_to_mcu.stats(), m_from_mcu.stats(),
            uart::match_frames(m_sent_to_mcu, framed_at_mcu, start_tolerance_ps(mcu.chip().clock())),
            uart::match_frames(sent_by_mcu, m_framed_at_host, cycles_to_ps(1, uart::kCp2102ClockHz))};
}

std::unique_ptr<BoardLineFaults> board_line_faults(const FaultSettings& f, const uart::Cp2102& cp2102,
                                                   const std::optional<FirmwareUsart>& usart, std::int64_t f_cpu_hz) {
    if (!f.uart.any()) return nullptr;
    const uart::BitClock host = cp2102.baud().bit_clock();
    return std::make_unique<BoardLineFaults>(f, host, usart ? uart::BitClock{usart->bit_cycles, f_cpu_hz} : host);
}

nlohmann::json board_faults_json(const FaultSettings& f, const BoardLineFaultResult& r) {
    return {{"seed", f.seed},
            {"uart_ber", f.uart.ber},
            {"uart_frame_loss_rate", f.uart.frame_loss_rate},
            {"to_mcu", direction_json(r.to_mcu_line, r.to_mcu)},
            {"from_mcu", direction_json(r.from_mcu_line, r.from_mcu)}};
}

std::string board_faults_text(const FaultSettings& f, const BoardLineFaultResult& r) {
    return fmt::format(FMT_STRING("faults (seed {}): UART BER {:g}, frames lost {:g}\n"), f.seed, f.uart.ber,
                       f.uart.frame_loss_rate) +
           direction_text("to the MCU", r.to_mcu_line, r.to_mcu) +
           direction_text("from the MCU", r.from_mcu_line, r.from_mcu);
}

}  // namespace cnc::sim
