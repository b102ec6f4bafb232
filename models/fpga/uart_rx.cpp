#include "fpga/uart_rx.hpp"

namespace cnc::fpga {

UartRx::UartRx(const sc_core::sc_module_name& name, const FpgaConfig& cfg)
    : sc_module(name),
      rx("rx"),
      rx_data("rx_data"),
      rx_valid("rx_valid"),
      m_cfg(cfg),
      m_clock(clock_grid(cfg)),
      m_timing(cfg),
      m_writer("writer") {
    SC_HAS_PROCESS(UartRx);
    SC_METHOD(record_line);  // also runs at initialisation to catch a line that starts low
    sensitive << rx;
    SC_THREAD(fsm_thread);
}

void UartRx::record_line() {
    ++m_activations;
    m_line.add(now_ps(), rx.read());
    m_line_changed.notify();
}

bool UartRx::fsm_level(std::int64_t n) const {
    return m_line.level_before(m_clock.at(n - UartRxTiming::kSyncStages));
}

void UartRx::wait_until_edge(std::int64_t n) {
    const TimePs t = m_clock.at(n);
    const TimePs now = now_ps();
    if (t > now) {
        wait(ps(t - now));
        ++m_activations;
    }
}

std::int64_t UartRx::wait_for_start(std::int64_t n_idle) {
    std::int64_t n = n_idle;
    for (;;) {
        // The level seen at edge n is final once every change before edge n-2 has happened.
        wait_until_edge(n - UartRxTiming::kSyncStages);
        if (!fsm_level(n)) return n;
        const auto change = m_line.first_change_at_or_after(m_clock.at(n - UartRxTiming::kSyncStages));
        if (!change) {
            wait(m_line_changed);
            ++m_activations;
            continue;
        }
        // The line fell after the level edge n saw; the first edge that can see it (a glitch that rose
        // again before that edge is invisible and the loop moves on to the next change).
        n = m_clock.first_after(*change) + UartRxTiming::kSyncStages;
    }
}

void UartRx::fsm_thread() {
    std::int64_t n_idle = 1;  // edge 0 is the reset state
    for (;;) {
        const std::int64_t n0 = wait_for_start(n_idle);
        const std::int64_t check = n0 + m_timing.start_check;
        wait_until_edge(check - UartRxTiming::kSyncStages);
        if (fsm_level(check)) {  // start bit gone at HALF_BIT: glitch
            n_idle = n0 + m_timing.idle_after_glitch();
            continue;
        }
        const std::int64_t stop = n0 + m_timing.stop;
        wait_until_edge(stop - UartRxTiming::kSyncStages);
        std::uint8_t byte = 0;
        for (int i = 0; i < 8; ++i) {
            if (fsm_level(n0 + m_timing.bit(i))) byte = static_cast<std::uint8_t>(byte | (1U << i));
        }
        if (fsm_level(stop)) {
            ++m_bytes;
            m_writer.at(m_clock.at(stop), [this, byte] {
                rx_data.write(byte);
                rx_valid.write(true);
            });
            m_writer.at(m_clock.at(stop + 1), [this] { rx_valid.write(false); });
        } else {
            ++m_framing_errors;  // seed 000 §5.2.1: a bad stop bit drops the byte silently
        }
        n_idle = n0 + m_timing.idle_after_stop();
        m_line.forget_before(m_clock.at(n_idle - UartRxTiming::kSyncStages));
    }
}

}  // namespace cnc::fpga
