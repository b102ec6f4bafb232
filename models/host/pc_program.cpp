#include "host/pc_program.hpp"
#include "common/sc_time.hpp"

namespace cnc::host {

PcProgram::PcProgram(const sc_core::sc_module_name& name, const SenderConfig& cfg, uart::Cp2102& port,
                     std::vector<seed003::Transfer> transfers)
    : sc_module(name), m_cfg(cfg), m_port(port), m_transfers(std::move(transfers)) {
    SC_HAS_PROCESS(PcProgram);
    SC_THREAD(run);
}

void PcProgram::set_waits(const UnitWaits& waits) { m_waits = waits; }

std::uint8_t PcProgram::wait_for_confirm() {
    while (m_port.in_waiting() == 0) sc_core::wait(m_port.data_event());
    const std::uint8_t b = *m_port.read_byte();
    if (b != seed003::kConfirmByte) ++m_unexpected;
    return b;
}

void PcProgram::run() {
    m_port.reset_input_buffer();  // PurgeComm(RX | TX) comes before the Sleep (seed 003 §3.4)
    wait_ps(m_cfg.settle_ps);
    for (std::size_t i = 0; i < m_transfers.size(); ++i) {
        wait_ps(m_cfg.packet_processing_ps);
        const std::vector<std::uint8_t>& bytes = m_transfers[i].bytes;
        for (std::size_t k = 0; k < bytes.size(); ++k) {
            const std::uint8_t b = bytes[k];
            PcWrite w;
            w.transfer = i;
            w.byte = b;
            w.confirm = wait_for_confirm();
            w.t_confirm_ps = now_ps();
            if (k == 0 && i < m_waits.before_s.size()) {
                wait_ps(s_to_ps(m_waits.before_s[i]));
            }
            w.t_write_ps = now_ps();
            wait_ps(m_cfg.write_latency_ps);
            m_port.usb_write(&b, 1);
            m_writes.push_back(w);
        }
    }
    wait_ps(s_to_ps(m_waits.after_last_s));
    m_finished = true;
    m_t_end = now_ps();
}

}  // namespace cnc::host
