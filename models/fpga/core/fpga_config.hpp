// Parameters of the seed 000 FPGA (DE1-SoC, Verilog of Π.1-Π.6): clock, UART bit counts, step_gen timing,
// and the two switches where the appendix departs from the text (init packet wiring, 32-bit period product).
#pragma once
#include <cstdint>

#include "common/clock_grid.hpp"
#include "common/units.hpp"

namespace cnc::fpga {

// seed 000 §3.4.5 computes period_sub = (num/feed)*abs_dom/abs_sub without overflow; the appendix step_gen
// evaluates the product at 32 bits and wraps.
enum class PeriodArithmetic { Exact, Wrap32 };

// Our option on seed 000 §7.2's trapezoidal or S-curve ramps on the FPGA (core/step_ramp.hpp): none is the seed's
// step_gen.
enum class StepRamp { None, Trapezoidal, SCurve };

struct FpgaConfig {
    std::uint32_t clk_hz = 50'000'000;               // seed 000 §5.1.1: DE1-SoC CLOCK_50
    std::uint32_t uart_full_bit_cycles = 434;        // seed 000 §5.2.1 FULL_BIT; uart_tx CLK_FREQ/BAUD_RATE (§5.2.2)
    std::uint32_t uart_half_bit_cycles = 217;        // seed 000 §5.2.1 HALF_BIT (mid-start-bit check)
    std::uint32_t watchdog_cycles = 5'000'000;       // seed 000 §5.2.3 TIMEOUT_CYCLES: 100 ms inter-byte watchdog
    std::uint32_t pulse_high_cycles = 100;           // seed 000 §5.2.4 PULSE_HIGH: 2 us STEP high
    std::uint32_t dir_settle_cycles = 200;           // seed 000 §5.2.4 DIR_SETTLE: 4 us
    std::uint32_t numerator_default = 18'750'000;    // seed 000 §5.2.4 reset value of num_x/num_y (160 steps/mm)
    std::uint32_t feed_zero_period_cycles = 62'500;  // step_gen.v: both periods when feed_rate == 0 (unexplained)
    bool init_packet_wired = true;                   // false = appendix top.v: cfg_valid/numerators unconnected
    PeriodArithmetic period_arithmetic = PeriodArithmetic::Exact;  // Exact = the text, Wrap32 = the appendix
    StepRamp ramp = StepRamp::None;
    // The ramp's registers until an init packet sets them: 1000 mm/s^2 and a 5 mm/s start at 160 steps/mm
    // (NUMERATOR_DEFAULT's machine), in step_ramp.hpp's fixed point at 50 MHz.
    std::uint32_t ramp_accel_default = 18'014;  // 160,000 steps/s^2 x 2^48 / (50 MHz)^2
    std::uint32_t ramp_start_default = 68'719;  // 800 steps/s x 2^32 / 50 MHz
    std::uint32_t ramp_jerk_default =
        154'742'505;          // the S-curve's: 16e6 steps/s^3 (100,000 mm/s^3) x 2^80 / (50 MHz)^3
    bool packet_crc = false;  // our option on seed 000 §7.2's CRC: packets checked, NAK, repeats (decoder core)
    // Our option on seed 000 §7.2's command queue and FIFO packet buffer: packets queued ahead of step_gen
    // (packet_queue.hpp); 0: none, the seed's stop-and-wait.
    int queue_depth = 0;
    // Our option on seed 000 §7.2's e-stop and interlock inputs (top.hpp): the e-stop halts step_gen and the laser
    // for good, the lid held open keeps the laser off.
    bool estop_input = false;
    bool interlock_input = false;
    // Our option on seed 000 §7.2's PWM laser power (core/laser_pwm.hpp): the laser pin's PWM period in clocks, each
    // motion packet carrying its high time; 0: none, the seed's on/off laser.
    std::uint32_t laser_pwm_period_cycles = 0;
    ClockDeviation clock;  // the board oscillator's offset and jitter (all zero: an ideal CLOCK_50)
};

// The edges of the FPGA's clock: clk_hz as this board's oscillator makes it.
[[nodiscard]] ClockGrid clock_grid(const FpgaConfig& cfg);

// Rejects values the RTL registers cannot hold (cnc::BadInput naming the key): uart_rx's 10-bit count,
// uart_tx's 9-bit clk_count, step_gen's 9-bit dir_cnt, packet_decoder's 23-bit timeout_cnt.
void validate(const FpgaConfig& cfg);

}  // namespace cnc::fpga
