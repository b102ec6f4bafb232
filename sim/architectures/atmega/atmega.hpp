// The atmega architecture of seed 003: the PC program (CAD2G V42) -> CP2102 -> ATmega328P running the seed 003
// firmware (simulated instruction by instruction, timers and USART cycle-exact) -> DRV8825 (EN driven by the
// firmware) -> steppers -> belts. README.md in this folder says what is modelled.
#pragma once
#include "architectures/architecture.hpp"

namespace cnc::sim {

struct ArchRun;
struct Job;

namespace atmega {

// Its registry entry (architectures/registry.hpp).
struct Entry {
    static const Architecture& architecture();  // atmega.cpp
    // atmega_controller.cpp: BadInput for a bad avr.pins or avr.firmware; unavailable.cpp in a build without the
    // AVR model refuses the architecture.
    static ArchRun run(const Scenario& s, const Job& job);
};

}  // namespace atmega

}  // namespace cnc::sim
