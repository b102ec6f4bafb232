// The spi-fpga architecture of seed 004: a Machinekit-style host (trajectory planner, servo thread) -> SPI mode 0
// frames -> FPGA (SPI slave, FIFO, pulse generators, step counters) -> DRV8825 -> steppers -> belts. README.md in
// this folder says what is modelled.
#pragma once
#include "architectures/architecture.hpp"

namespace cnc::sim {

struct ArchRun;
struct Job;

namespace spi_fpga {

// Its registry entry (architectures/registry.hpp).
struct Entry {
    static const Architecture& architecture();              // spi_fpga.cpp
    static ArchRun run(const Scenario& s, const Job& job);  // spi_fpga_controller.cpp
};

}  // namespace spi_fpga

}  // namespace cnc::sim
