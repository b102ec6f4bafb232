// What the STEP-input fault (faults.step_loss_rate) did: the pulses each DRV8825 dropped, and where that leaves the
// tool, in the architecture's report section.
#pragma once
#include "run/arch_run.hpp"
#include "run/machine.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

// Adds details["step_faults"] and a summary line.
void add_step_fault_report(const Machine& machine, const Scenario& s, ArchRun& run);

}  // namespace cnc::sim
