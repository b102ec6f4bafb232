#include "fpga/core/fpga_config.hpp"

#include <string>

#include "common/bad_input.hpp"

namespace cnc::fpga {

ClockGrid clock_grid(const FpgaConfig& cfg) {
    return ClockGrid(cfg.clk_hz, cfg.clock, "fpga: clock");
}

namespace {
void require(bool ok, const char* key, const std::string& what) {
    if (!ok) throw BadInput(std::string("fpga: ") + key, what);
}
}  // namespace

void validate(const FpgaConfig& cfg) {
    require(cfg.clk_hz > 0 && kPsPerSec % cfg.clk_hz == 0, "clk_hz",
            "must divide 1e12 so that a clock period is a whole number of ps");
    // uart_tx compares its 9-bit clk_count with FULL_BIT-1; uart_rx counts to FULL_BIT in 10 bits.
    require(cfg.uart_full_bit_cycles >= 2 && cfg.uart_full_bit_cycles <= 512, "uart_full_bit_cycles",
            "must be in 2..512 (uart_tx clk_count is 9 bits)");
    require(cfg.uart_half_bit_cycles >= 1 && cfg.uart_half_bit_cycles < cfg.uart_full_bit_cycles,
            "uart_half_bit_cycles", "must be in 1..uart_full_bit_cycles-1");
    require(cfg.watchdog_cycles >= 1 && cfg.watchdog_cycles < (1U << 23), "watchdog_cycles",
            "must be in 1..2^23-1 (timeout_cnt is 23 bits)");
    require(cfg.pulse_high_cycles >= 1, "pulse_high_cycles", "must be >= 1");
    require(cfg.dir_settle_cycles >= 1 && cfg.dir_settle_cycles < 512, "dir_settle_cycles",
            "must be in 1..511 (dir_cnt is 9 bits)");
    require(
        cfg.laser_pwm_period_cycles == 0 || (cfg.laser_pwm_period_cycles >= 2 && cfg.laser_pwm_period_cycles <= 65535),
        "laser_pwm_period_cycles", "must be 0 (no PWM) or in 2..65535 (laser_ctrl's counter is 16 bits)");
}

}  // namespace cnc::fpga
