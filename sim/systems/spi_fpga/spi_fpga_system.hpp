// The spi-fpga architecture (seed 004).
#pragma once
#include "run/arch_run.hpp"
#include "run/job.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

ArchRun run_spi_fpga(const Scenario& scenario, const Job& job);

}  // namespace cnc::sim
