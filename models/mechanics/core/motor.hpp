// The interface between a stepper driver and a motor model.
//
// The driver tells the motor when its commanded electrical position changes (and when its outputs are
// enabled); the motor answers the shaft angle at a time. An ideal motor follows the command instantly; a
// dynamic model (currents, torque, inertia, detent, load: docs/mechanics.md) integrates its state forward between
// the calls and can then lag, overshoot or slip. Both are queried with non-decreasing times, not earlier
// than the last call they were told about: models only integrate forward.
#pragma once
#include <cstdint>

#include "common/units.hpp"

namespace cnc::mech {

class StepperMotor {
public:
    virtual ~StepperMotor() = default;

    // The commanded position became `microstep_index` at t (in units of 1/microsteps_per_full_step of a full
    // step; the DRV8825 model always reports 1/32 units so that mode changes mid-run are exact). The
    // electrical angle and winding currents follow from it (drv8825_modes.hpp).
    virtual void on_microstep(TimePs t_ps, std::int64_t microstep_index, int microsteps_per_full_step) = 0;
    // The driver's outputs were enabled (holding torque) or disabled (windings off: the rotor is free).
    virtual void on_enable(TimePs t_ps, bool enabled) = 0;
    [[nodiscard]] virtual double shaft_angle_deg(TimePs t_ps) const = 0;
};

}  // namespace cnc::mech
