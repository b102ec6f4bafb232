// The spi-fpga architecture (seed 004): the host plans the G-code (host/core/planner) and closes the position loop
// on its servo thread (host/servo), one full-duplex SPI transfer per period (spi/) to the FPGA (fpga/spi: SPI
// slave, FIFO, period-counter pulse generators, step counters), which drives the shared DRV8825 machine.
#pragma once
#include "run/arch_run.hpp"
#include "run/job.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

// BadInput for a steps-file job (this host plans G-code) and for a velocity limit the rate word cannot hold.
ArchRun run_spi_fpga(const Scenario& scenario, const Job& job);

}  // namespace cnc::sim
