// The atmega architecture of seed 003: the PC program (CAD2G V42) -> CP2102 -> ATmega328P running the seed 003
// firmware (simulated instruction by instruction, timers and USART cycle-exact) -> DRV8825 (EN driven by the
// firmware) -> steppers -> belts.
#pragma once
#include "run/arch_run.hpp"
#include "run/job.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

// Throws BadInput for a steps-file job (a seed 000 format), a bad avr.pins or avr.firmware.
ArchRun run_atmega(const Scenario& scenario, const Job& job);

}  // namespace cnc::sim
