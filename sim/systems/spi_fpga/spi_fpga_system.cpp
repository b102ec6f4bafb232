#include "systems/spi_fpga/spi_fpga_system.hpp"

#include "common/bad_input.hpp"

namespace cnc::sim {

ArchRun run_spi_fpga(const Scenario& scenario, const Job&) {
    throw BadInput(scenario.file + ": scenario.architecture", "'spi-fpga' is not implemented yet (issue 4)");
}

}  // namespace cnc::sim
