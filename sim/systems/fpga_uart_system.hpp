// The fpga-uart architecture of seed 000: host CAM and send_steps.py -> CP2102 -> FPGA (uart_rx,
// packet_decoder, step_gen, laser_ctrl, uart_tx) -> DRV8825 -> steppers -> belts.
#pragma once
#include "run/arch_run.hpp"
#include "run/job.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

ArchRun run_fpga_uart(const Scenario& scenario, const Job& job);

}  // namespace cnc::sim
