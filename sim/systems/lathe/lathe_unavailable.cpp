#include "common/bad_input.hpp"
#include "systems/lathe/lathe_system.hpp"

namespace cnc::sim {

// This build has no AVR model (CNC_WITH_AVR=OFF: avr-gcc or libsimavr missing).
ArchRun run_lathe_sync(const Scenario& scenario, const Job&) {
    throw BadInput(scenario.file + ": scenario.architecture",
                   "'lathe-sync' needs the ATmega16 model: rebuild with CNC_WITH_AVR=ON (avr-gcc, libsimavr)");
}

}  // namespace cnc::sim
