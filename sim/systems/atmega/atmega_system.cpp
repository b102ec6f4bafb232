#include "systems/atmega/atmega_system.hpp"

#include "common/bad_input.hpp"

namespace cnc::sim {

ArchRun run_atmega(const Scenario& scenario, const Job&) {
    throw BadInput(scenario.file + ": scenario.architecture", "'atmega' is not implemented yet (issue 3)");
}

}  // namespace cnc::sim
