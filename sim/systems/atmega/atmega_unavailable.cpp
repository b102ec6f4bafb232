#include "common/bad_input.hpp"
#include "systems/atmega/atmega_system.hpp"

namespace cnc::sim {

// This build has no ATmega328P model (CNC_WITH_AVR=OFF: avr-gcc or libsimavr missing).
ArchRun run_atmega(const Scenario& scenario, const Job&) {
    throw BadInput(scenario.file + ": scenario.architecture",
                   "'atmega' needs the ATmega328P model: rebuild with CNC_WITH_AVR=ON (avr-gcc, libsimavr)");
}

}  // namespace cnc::sim
