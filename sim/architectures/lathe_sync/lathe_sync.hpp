// The lathe-sync architecture (seed 002's electronic leadscrew): the operator script run on the chip-level lathe
// (models/lathe/rig: the ATmega16 model with the lathe_sync firmware, L298, motor, drive train, encoders, keypad),
// measured as docs/metrics.md "Lathe" defines. It runs no job: the machinist's keys are the program, and it drives
// a spindle and a leadscrew, not the XY machine.
#pragma once
#include "architectures/architecture.hpp"

namespace cnc::sim {

struct ArchRun;
struct Job;

namespace lathe_sync {

// Its registry entry (architectures/registry.hpp).
struct Entry {
    static const Architecture& architecture();  // lathe_sync.cpp
    // lathe_sync_run.cpp; unavailable.cpp in a build without the AVR model refuses the architecture.
    static ArchRun run(const Scenario& s, const Job& job);
};

}  // namespace lathe_sync

}  // namespace cnc::sim
