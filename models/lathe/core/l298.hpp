// One full bridge of the ST L298 as seed 002 wires it (§2.3, §2.5.3): EnA = OC1A (PD5, the PWM), In1 = DIR1 (PD0),
// In2 = DIR2 (PD1), Vs = 24 V. Sign-magnitude drive: the direction on In1/In2, the magnitude as the PWM on EnA.
// L298 datasheet, "Bidirectional DC motor control" table: EnA high with In1 != In2 drives (Out1 to Vs when In1
// is high), In1 == In2 is a fast motor stop (both lower or both upper transistors on: dynamic braking), EnA low
// turns every transistor off (free running). The total saturation drop of a conducting pair is taken as 2 V
// (§2.3), so the motor sees kBridgeVolts = 22 V.
#pragma once
#include "lathe/core/dc_motor.hpp"

namespace cnc::lathe {

class L298 {
public:
    // Input pins (logic levels).
    bool en_a = false;
    bool in1 = false;
    bool in2 = false;

    [[nodiscard]] BridgeMode mode() const {
        return !en_a ? BridgeMode::Coast : in1 != in2 ? BridgeMode::Drive : BridgeMode::Brake;
    }
    // Out1 - Out2 while driving (In1 high: Out1 at Vs less the drop, Out2 at ground).
    [[nodiscard]] double drive_volts() const { return in1 ? kBridgeVolts : -kBridgeVolts; }
};

}  // namespace cnc::lathe
