// The DRV8825's configuration as a board wires it: its timing limits, how strictly it judges pulses, and which DIR
// level is the positive direction.
#pragma once
#include "mechanics/core/drv8825_timing.hpp"

namespace cnc::mech {

struct Drv8825Config {
    DriverLimits limits{};
    // false (default): every rising edge while enabled is a step, whatever its timing (violations are only
    // counted). true: a pulse whose preceding low time < tWL is ignored at its rising edge, and a pulse whose
    // high time < tWH is retracted at its falling edge (the motor is commanded back to where it was: the
    // model cannot know a pulse is too short before it ends, so it moves on the rise as for a valid pulse).
    // This is the pessimistic reading of the data sheet minimums; real chips often accept shorter pulses.
    bool strict = false;
    bool dir_high_is_positive = true;  // seed 000 §2.3: the DIR-to-direction mapping depends on the wiring
    // A fault on the STEP input (a noisy or loose wire, faults.step_loss_rate): each rising edge that would step is
    // lost with this probability, drawn per edge from the seed and the driver's line (common/splitmix64.hpp).
    double step_loss_rate = 0.0;
    std::uint64_t fault_seed = 1;
    std::uint64_t fault_line = 0;
};

}  // namespace cnc::mech
