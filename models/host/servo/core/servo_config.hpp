// Settings of the spi-fpga host's servo thread (seed 004 §4.1, §4.3.2: Machinekit's motion controller and the SPI
// driver's read/update/write on one real-time thread; values from LinuxCNC's hostmot2 stepgen).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "common/geometry.hpp"
#include "common/units.hpp"
#include "host/servo/core/latency.hpp"
#include "host/servo/core/stepgen_law.hpp"

namespace cnc::host::servo {

inline constexpr std::size_t kAxes = 2;  // X and Y, as the FPGA's frame

struct AxisServoConfig {
    double steps_per_mm = 160.0;
    double max_velocity_mm_per_s = 100.0;  // the planner's axis limits
    double max_accel_mm_per_s2 = 1000.0;
};

struct ServoConfig {
    TimePs period_ps = kPsPerMs;  // LinuxCNC's default servo thread, 1 ms (seed 004 §4.1 gives no period)
    LatencyConfig latency;
    std::uint64_t seed = 1;       // the scenario seed: latency draws
    double position_gain = 0.5;   // hm2 stepgen: 0.5 * error_at_match / period
    double deadband_steps = 1.0;  // Remora's default (remora-spi.c `deadband`); see stepgen_law.hpp
    // stepgen limits above the planner's: LinuxCNC's ini reference puts STEPGEN_MAXVEL/MAXACCEL 1-10 % above the
    // joint's, pncconf/stepconf-generated configs 25 %; the loop needs the headroom to catch up its lag.
    double stepgen_margin = 0.25;
    std::array<AxisServoConfig, 2> axes{};
    geom::Vec2 origin_mm{};  // machine position at step count 0 (the FPGA counters start at 0)
    std::uint32_t clk_hz = 50'000'000;
    std::uint32_t min_period_cycles = 101;  // the FPGA's shortest STEP period (pulse + 1 clock)
};

[[nodiscard]] double period_s(const ServoConfig& cfg);
// The law's limits for one axis: the planner's axis limits times (1 + stepgen_margin), in steps.
[[nodiscard]] StepgenParams stepgen_params(const ServoConfig& cfg, std::size_t axis);
// Rate word period of a landing pulse (servo_core.hpp): two servo periods, in FPGA clocks.
[[nodiscard]] std::uint32_t landing_period_cycles(const ServoConfig& cfg);

}  // namespace cnc::host::servo
