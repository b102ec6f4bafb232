// Motor curves from the axis model: pull-out torque against step rate, the load's required torque, and
// the highest start-stop (pull-in) rate for the load.
//
// Pull-out torque at a step rate: the rotor turns at exactly the synchronous speed, a constant load angle
// behind the command (the driver's microstep staircase at that rate); the winding currents are integrated
// through the DRV8825 regulation (drv8825_current.hpp) until periodic, and the mean electromagnetic torque
// over an electrical period is the torque the motor delivers at that load angle. The pull-out torque is its
// maximum over load angles: the largest steady load the motor carries at that speed.
// Pull-in rate: the full axis model (inertias, belt, friction) starts from rest with the command jumping
// straight to the rate, runs for kPullInRunS, stops dead and settles; the rate passes if no step was lost.
// Rates are scanned upwards in 5 % increments from kPullInStartHz and the boundary refined by bisection.
#pragma once
#include <vector>

#include "mechanics/core/axis_ode.hpp"

namespace cnc::mech {

inline constexpr double kPullInRunS = 0.1;
inline constexpr double kPullInStartHz = 10.0;  // full steps per second

// Mean electromagnetic torque at a constant load angle (electrical rad, > 0: rotor behind the command).
[[nodiscard]] double synchronous_torque_nm(const AxisParams& p, int microsteps, double full_steps_per_s,
                                           double load_angle_rad);
// Pull-out torque at a step rate (full steps per second).
[[nodiscard]] double pull_out_torque_nm(const AxisParams& p, int microsteps, double full_steps_per_s);
// Shaft torque the load needs at a constant speed (friction of rails, screw and motor), N m.
[[nodiscard]] double required_torque_nm(const AxisParams& p, double full_steps_per_s);
// Extra shaft torque to accelerate rotor and carriage at accel_mm_s2.
[[nodiscard]] double acceleration_torque_nm(const AxisParams& p, double accel_mm_s2);
// Whether the axis starts at this rate from rest and stops dead without losing a step.
[[nodiscard]] bool starts_without_loss(const AxisParams& p, int microsteps, double full_steps_per_s);
// The highest such rate (full steps per second), searched up to max_full_steps_per_s.
[[nodiscard]] double pull_in_rate(const AxisParams& p, int microsteps, double max_full_steps_per_s);

}  // namespace cnc::mech
