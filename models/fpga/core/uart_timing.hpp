// Cycle schedules of uart_rx (Π.2) and uart_tx (Π.3), derived from their always blocks, as offsets in clock
// edges so that the event-driven modules never tick.
#pragma once
#include <cstdint>
#include <vector>

#include "fpga/core/fpga_config.hpp"

namespace cnc::fpga {

// uart_rx. Offsets are relative to n0, the first edge at which S_IDLE sees rx_s2 == 0.
// rx_s1 <= rx, rx_s2 <= rx_s1: the FSM at edge n works on the line level that rx_s1 sampled at edge n-2.
struct UartRxTiming {
    static constexpr std::int64_t kSyncStages = 2;  // seed 000 §5.2.1: 2-FF synchroniser rx_s1, rx_s2
    std::int64_t start_check = 0;  // S_START at count == HALF_BIT: still low -> S_RECEIVE, else glitch -> S_IDLE
    std::int64_t first_bit = 0;    // S_RECEIVE at count == FULL_BIT: rx_shift[0]; then one bit every FULL_BIT
    std::int64_t full_bit = 0;
    std::int64_t stop = 0;  // S_STOP at count == FULL_BIT: rx_valid is high from this edge if rx_s2 == 1

    explicit UartRxTiming(const FpgaConfig& cfg);
    [[nodiscard]] std::int64_t bit(int i) const { return first_bit + full_bit * i; }
    // S_IDLE evaluates again from these edges (after a glitch, after the stop bit).
    [[nodiscard]] std::int64_t idle_after_glitch() const { return start_check + 1; }
    [[nodiscard]] std::int64_t idle_after_stop() const { return stop + 1; }
};

struct CycleEdge {
    std::int64_t cycle = 0;  // edge offset
    bool level = false;      // level from that edge on
};

// uart_tx. Offsets are relative to the edge at which tx_start is high (IDLE sees it one edge later).
struct UartTxFrame {
    std::vector<CycleEdge> tx_changes;  // changes of the idle-high tx line: start bit, data LSB first, stop
    std::int64_t busy_rise = 0;
    std::int64_t busy_fall = 0;  // STOP ends at clk_count == FULL_BIT-1
    std::int64_t idle_from = 0;  // first edge at which IDLE can see the next tx_start
};
[[nodiscard]] UartTxFrame uart_tx_frame(std::uint8_t byte, const FpgaConfig& cfg);

}  // namespace cnc::fpga
