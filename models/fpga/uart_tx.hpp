// uart_tx (seed 000 §5.2.2, Π.3): IDLE/START/DATA/STOP, FULL_BIT cycles per bit, LSB first; the whole frame is
// scheduled when IDLE sees tx_start.
#pragma once
#include <cstdint>
#include <systemc>

#include "fpga/core/fpga_config.hpp"
#include "fpga/core/uart_timing.hpp"
#include "fpga/timed_writer.hpp"

namespace cnc::fpga {

class UartTx : public sc_core::sc_module {
public:
    sc_core::sc_in<std::uint8_t> tx_data;
    sc_core::sc_in<bool> tx_start;
    sc_core::sc_out<bool> tx_busy;
    sc_core::sc_out<bool> tx;

    UartTx(const sc_core::sc_module_name& name, const FpgaConfig& cfg);
    [[nodiscard]] std::uint64_t activations() const { return m_activations + m_writer.activations(); }

private:
    void on_tx_start();

    const FpgaConfig m_cfg;
    const ClockGrid m_clock;
    std::int64_t m_idle_from = 0;  // first edge at which the FSM is IDLE again
    TimedWriter m_writer;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
