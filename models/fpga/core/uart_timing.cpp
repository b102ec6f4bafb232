#include "fpga/core/uart_timing.hpp"

namespace cnc::fpga {

UartRxTiming::UartRxTiming(const FpgaConfig& cfg)
    : start_check(cfg.uart_half_bit_cycles),
      // S_START -> S_RECEIVE loads count = 1, so count == FULL_BIT comes FULL_BIT edges later.
      first_bit(cfg.uart_half_bit_cycles + cfg.uart_full_bit_cycles),
      full_bit(cfg.uart_full_bit_cycles),
      // After bit 7 S_STOP starts with count = 1 (the listing's lost lines 0075-0077 are taken as not
      // touching count: see models/fpga/README.md), so the stop bit is sampled FULL_BIT after bit 7.
      stop(cfg.uart_half_bit_cycles + 9 * static_cast<std::int64_t>(cfg.uart_full_bit_cycles)) {}

UartTxFrame uart_tx_frame(std::uint8_t byte, const FpgaConfig& cfg) {
    const std::int64_t bit = cfg.uart_full_bit_cycles;
    UartTxFrame f;
    f.busy_rise = 1;               // IDLE sees tx_start: tx_busy <= 1, state <= START
    const std::int64_t start = 2;  // first START edge drives tx <= 0
    bool level = true;             // idle high
    auto drive = [&](std::int64_t cycle, bool l) {
        if (l != level) f.tx_changes.push_back({cycle, l});
        level = l;
    };
    drive(start, false);
    for (int i = 0; i < 8; ++i) drive(start + bit * (i + 1), ((byte >> i) & 1U) != 0);  // LSB first
    drive(start + bit * 9, true);                                                       // STOP
    f.busy_fall = start + bit * 10 - 1;  // STOP's clk_count == FULL_BIT-1 edge: tx_busy <= 0, state <= IDLE
    f.idle_from = f.busy_fall + 1;
    return f;
}

}  // namespace cnc::fpga
