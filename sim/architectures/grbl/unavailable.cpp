#include "architectures/grbl/grbl.hpp"
#include "common/bad_input.hpp"
#include "run/arch_run.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim::grbl {

// This build has no ATmega328P model (CNC_WITH_AVR=OFF: avr-gcc or libsimavr missing).
ArchRun Entry::run(const Scenario& s, const Job&) {
    throw BadInput(s.file + ": scenario.architecture",
                   "'grbl' needs the ATmega328P model: rebuild with CNC_WITH_AVR=ON (avr-gcc, libsimavr)");
}

}  // namespace cnc::sim::grbl
