// Our option on seed 000 §7.2's PWM laser power (fpga.laser_pwm): laser_ctrl counts the FPGA clock from 0 to
// period - 1 while step_gen is busy, restarting at each pkt_valid, and the laser pin is high while the count is below
// the move's high time (and the move engraves and runs: laser <= engrave & busy & !lid & count < high,
// rtl/laser_ctrl.v). The host sends the high time in each motion packet, S / S_max of the period, so the duty is
// high / period.
#pragma once
#include <cstdint>
#include <optional>

namespace cnc::fpga {

// The period in clocks when `pwm_hz` divides the clock into a whole number of clocks (to 1e-9 of a clock); none
// otherwise.
[[nodiscard]] std::optional<std::uint32_t> laser_pwm_period_cycles(std::uint32_t clk_hz, double pwm_hz);

// The high time of a move at power `s` on a machine whose full power is `s_max`: s / s_max of the period, rounded to
// the nearest clock; s is held to 0 .. s_max (grbl clamps S to its $30 the same way).
[[nodiscard]] std::uint16_t laser_high_cycles(double s, double s_max, std::uint32_t period_cycles);

// The count's value `since_restart` clocks after the pkt_valid that restarted it is below `high`.
[[nodiscard]] bool laser_pwm_high(std::int64_t since_restart, std::uint32_t high, std::uint32_t period_cycles);

// Clocks from `since_restart` to the next count whose level differs; none if the level never changes (high 0, or
// high >= period: held low or high).
[[nodiscard]] std::optional<std::int64_t> laser_pwm_next_change(std::int64_t since_restart, std::uint32_t high,
                                                                std::uint32_t period_cycles);

}  // namespace cnc::fpga
