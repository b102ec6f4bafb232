#include "architectures/lathe_sync/lathe_sync.hpp"
#include "common/bad_input.hpp"
#include "run/arch_run.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim::lathe_sync {

// This build has no AVR model (CNC_WITH_AVR=OFF: avr-gcc or libsimavr missing).
ArchRun Entry::run(const Scenario& s, const Job&) {
    throw BadInput(s.file + ": scenario.architecture",
                   "'lathe-sync' needs the ATmega16 model: rebuild with CNC_WITH_AVR=ON (avr-gcc, libsimavr)");
}

}  // namespace cnc::sim::lathe_sync
