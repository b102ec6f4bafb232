// uart_rx (seed 000 §5.2.1, Π.2): 8N1 receiver with a 2-FF synchroniser, mid-bit sampling from a HALF_BIT
// start check and FULL_BIT steps, rx_valid for one clock on a good stop bit. Event-driven: it wakes on rx
// changes and on the few edges where the FSM samples, and reads the sampled levels from a line history.
#pragma once
#include <cstdint>
#include <systemc>

#include "fpga/core/fpga_config.hpp"
#include "fpga/core/line_history.hpp"
#include "fpga/core/uart_timing.hpp"
#include "fpga/timed_writer.hpp"

namespace cnc::fpga {

class UartRx : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> rx;
    sc_core::sc_out<std::uint8_t> rx_data;
    sc_core::sc_out<bool> rx_valid;

    UartRx(const sc_core::sc_module_name& name, const FpgaConfig& cfg);

    [[nodiscard]] std::uint64_t bytes_received() const { return m_bytes; }
    [[nodiscard]] std::uint64_t framing_errors() const { return m_framing_errors; }
    [[nodiscard]] std::uint64_t activations() const { return m_activations + m_writer.activations(); }

private:
    void record_line();
    void fsm_thread();
    // First edge n >= n_idle at which S_IDLE sees rx_s2 == 0.
    std::int64_t wait_for_start(std::int64_t n_idle);
    // Level the FSM sees at edge n: rx as sampled into rx_s1 at edge n-2 (1 before edge 1: reset values).
    [[nodiscard]] bool fsm_level(std::int64_t n) const;
    void wait_until_edge(std::int64_t n);

    const FpgaConfig m_cfg;
    const ClockGrid m_clock;
    const UartRxTiming m_timing;
    LineHistory m_line{true};  // rx_s1/rx_s2 reset to 1: the line reads idle before time 0
    sc_core::sc_event m_line_changed;
    TimedWriter m_writer;
    std::uint64_t m_bytes = 0;
    std::uint64_t m_framing_errors = 0;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
