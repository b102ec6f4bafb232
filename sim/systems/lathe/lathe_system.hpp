// The lathe-sync architecture (seed 002's electronic leadscrew): the operator script run on the chip-level lathe
// (models/lathe/rig: the ATmega16 model with the lathe_sync firmware, L298, motor, drive train, encoders, keypad),
// measured as docs/metrics.md "Lathe" defines. It runs no job: the machinist's keys are the program.
#pragma once
#include "run/arch_run.hpp"
#include "run/job.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

ArchRun run_lathe_sync(const Scenario& scenario, const Job& job);

}  // namespace cnc::sim
