// What the host's init packet sets in the FPGA: seed 000 §4.6's NUMERATORs, and with the FPGA's ramp (fpga.ramp) its
// acceleration and start speed (and the S-curve's jerk) in step_gen's fixed point (fpga/core/step_ramp.hpp).
#pragma once
#include <cstdint>
#include <vector>

#include "architectures/fpga_uart/fpga_uart_settings.hpp"
#include "fpga/core/step_schedule.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim::fpga_uart {

struct InitRegisters {
    std::uint32_t num_x = 0;
    std::uint32_t num_y = 0;
    std::uint32_t ramp_accel = 0;  // with the ramp only
    std::uint32_t ramp_start = 0;
    std::uint32_t ramp_jerk = 0;  // with the S-curve only
};

// cnc::BadInput naming the key if the ramp's acceleration, start speed or jerk does not fit its register, or the
// S-curve's jerk phase would be shorter than a clock.
[[nodiscard]] InitRegisters init_registers(const Scenario& s, const FpgaUartSettings& f);

// The init packet's bytes, without the packet check's CRC.
[[nodiscard]] std::vector<std::uint8_t> init_packet(const InitRegisters& r, const FpgaUartSettings& f);

// What step_gen reads for a packet with these registers latched.
[[nodiscard]] fpga::MoveInputs move_inputs(std::int32_t steps_x, std::int32_t steps_y, std::uint16_t feed,
                                           const InitRegisters& r);

}  // namespace cnc::sim::fpga_uart
