// The grbl architecture: a G-code sender (as grbl's stream.py and Universal G-code Sender speak grbl's line
// protocol) -> CP2102 -> an ATmega328P at 16 MHz running the user's firmware (grbl 1.1h, or any on its protocol and
// pins) -> DRV8825 (one enable line) -> steppers -> belts. README.md in this folder says what is modelled.
#pragma once
#include "architectures/architecture.hpp"

namespace cnc::sim {

struct ArchRun;
struct Job;

namespace grbl {

// Its registry entry (architectures/registry.hpp).
struct Entry {
    static const Architecture& architecture();  // grbl.cpp
    // grbl_controller.cpp: BadInput for a bad avr.pins or avr.firmware; unavailable.cpp in a build without the AVR
    // model refuses the architecture.
    static ArchRun run(const Scenario& s, const Job& job);
};

}  // namespace grbl

}  // namespace cnc::sim
