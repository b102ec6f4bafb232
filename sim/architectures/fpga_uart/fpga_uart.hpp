// The fpga-uart architecture of seed 000: host CAM and send_steps.py -> CP2102 -> FPGA (uart_rx, packet_decoder,
// step_gen, laser_ctrl, uart_tx) -> DRV8825 -> steppers -> belts. README.md in this folder says what is modelled.
#pragma once
#include "architectures/architecture.hpp"

namespace cnc::sim {

struct ArchRun;
struct Job;

namespace fpga_uart {

// Its registry entry (architectures/registry.hpp).
struct Entry {
    static const Architecture& architecture();              // fpga_uart.cpp
    static ArchRun run(const Scenario& s, const Job& job);  // fpga_uart_controller.cpp
};

}  // namespace fpga_uart

}  // namespace cnc::sim
