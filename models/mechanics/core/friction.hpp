// Coulomb friction with sticking (Karnopp's model): outside a small speed band the friction is -F_c sign(v);
// inside it, it cancels the other forces on the body up to F_c and brings the speed to zero within
// kStickTimeS, so that a body at rest stays at rest (static friction holds a belt's residual stretch) and an
// axis can reach an exact rest, which the integrator then fast-forwards.
#pragma once
#include <algorithm>
#include <cmath>

namespace cnc::mech {

inline constexpr double kStickTimeS = 1e-3;

// `other`: the sum of the other forces (or torques) on the body; `inertia`: its mass (or moment of inertia);
// `band`: the speed below which the body may stick.
[[nodiscard]] inline double coulomb_friction(double level, double speed, double other, double inertia, double band) {
    if (std::abs(speed) >= band) return speed > 0.0 ? -level : level;
    return std::clamp(-other - inertia * speed / kStickTimeS, -level, level);
}

}  // namespace cnc::mech
