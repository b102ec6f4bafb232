// Coulomb friction with sticking (Karnopp's model): outside a small speed band the friction is -F_c sign(v);
// inside it, it cancels the other forces on the body up to F_c and brings the speed to zero within
// kStickTimeS, so that a body at rest stays at rest (static friction holds a belt's residual stretch) and an
// axis can reach an exact rest, which the integrator then fast-forwards.
#pragma once
#include <algorithm>
#include <cmath>

namespace cnc::mech {

inline constexpr double kStickTimeS = 1e-3;

// Where a body's speed is against the stick band: the friction is smooth in the speed within each (the
// integrator ends a step where a body changes side).
enum class FrictionMode { Stuck, Forward, Backward };

[[nodiscard]] inline FrictionMode friction_mode(double speed, double band) {
    if (speed >= band) return FrictionMode::Forward;
    if (speed <= -band) return FrictionMode::Backward;
    return FrictionMode::Stuck;
}

// How far inside `mode` the speed is, in bands: >= 0 while the body stays in it (> 0 for Stuck).
[[nodiscard]] inline double friction_margin(FrictionMode mode, double speed, double band) {
    switch (mode) {
        case FrictionMode::Forward:
            return speed / band - 1.0;
        case FrictionMode::Backward:
            return -speed / band - 1.0;
        case FrictionMode::Stuck:
            break;
    }
    return 1.0 - std::abs(speed) / band;
}

// `other`: the sum of the other forces (or torques) on the body; `inertia`: its mass (or moment of inertia).
[[nodiscard]] inline double coulomb_friction(FrictionMode mode, double level, double speed, double other,
                                             double inertia) {
    switch (mode) {
        case FrictionMode::Forward:
            return -level;
        case FrictionMode::Backward:
            return level;
        case FrictionMode::Stuck:
            break;
    }
    return std::clamp(-other - inertia * speed / kStickTimeS, -level, level);
}

// `band`: the speed below which the body may stick.
[[nodiscard]] inline double coulomb_friction(double level, double speed, double other, double inertia, double band) {
    return coulomb_friction(friction_mode(speed, band), level, speed, other, inertia);
}

}  // namespace cnc::mech
