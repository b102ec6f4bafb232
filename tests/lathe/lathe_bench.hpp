// The lathe rig (models/lathe/rig) with this build's lathe_sync firmware by default.
#pragma once
#include "lathe/rig/lathe_rig.hpp"

namespace cnc::lathe::test {

using avr::Cycle;

inline constexpr double kCycleS = 1.0 / 8e6;

struct LatheBench : LatheRig {
    explicit LatheBench(double spindle_rpm = 0.0, const char* elf = LATHE_SYNC_ELF)
        : LatheRig(config(elf, spindle_rpm)) {}

    static LatheRigConfig config(const char* elf, double spindle_rpm) {
        LatheRigConfig c;
        c.firmware_elf = elf;
        c.spindle_rpm = spindle_rpm;
        return c;
    }
};

}  // namespace cnc::lathe::test
