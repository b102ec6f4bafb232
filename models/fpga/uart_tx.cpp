#include "fpga/uart_tx.hpp"

namespace cnc::fpga {

UartTx::UartTx(const sc_core::sc_module_name& name, const FpgaConfig& cfg)
    : sc_module(name),
      tx_data("tx_data"),
      tx_start("tx_start"),
      tx_busy("tx_busy"),
      tx("tx"),
      m_cfg(cfg),
      m_clock(clock_grid(cfg)),
      m_writer("writer") {
    SC_HAS_PROCESS(UartTx);
    tx.initialize(true);  // seed 000 §5.2.2: reset drives the line idle high
    SC_METHOD(on_tx_start);
    sensitive << tx_start;
    dont_initialize();
}

void UartTx::on_tx_start() {
    ++m_activations;
    if (!tx_start.read()) return;
    const std::int64_t s = m_clock.last_at_or_before(now_ps());  // tx_start high at edge s, seen by IDLE at s+1
    if (s + 1 < m_idle_from) return;                             // START/DATA/STOP do not look at tx_start
    const UartTxFrame frame = uart_tx_frame(tx_data.read(), m_cfg);
    const auto at = [this, s](std::int64_t offset) { return m_clock.at(s + offset); };
    m_writer.at(at(frame.busy_rise), [this] { tx_busy.write(true); });
    for (const CycleEdge& e : frame.tx_changes) {
        const bool level = e.level;
        m_writer.at(at(e.cycle), [this, level] { tx.write(level); });
    }
    m_writer.at(at(frame.busy_fall), [this] { tx_busy.write(false); });
    m_idle_from = s + frame.idle_from;
}

}  // namespace cnc::fpga
