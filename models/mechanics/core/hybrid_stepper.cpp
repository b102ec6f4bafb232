#include "mechanics/core/hybrid_stepper.hpp"

#include <cmath>
#include <string>

#include "common/bad_input.hpp"
#include "common/math_constants.hpp"

namespace cnc::mech {

namespace {

void require(bool ok, const char* what, double v) {
    if (!ok) throw BadInput("", std::string("motor ") + what + " (got " + std::to_string(v) + ")");
}

}  // namespace

double HybridStepperParams::full_step_rad() const {
    return kPi / (2.0 * rotor_teeth);
}

void validate(const HybridStepperParams& p) {
    require(p.rotor_teeth > 0, "rotor_teeth must be > 0", p.rotor_teeth);
    require(p.holding_torque_nm > 0.0, "holding_torque_nm must be > 0", p.holding_torque_nm);
    require(p.rated_current_a > 0.0, "rated_current_a must be > 0", p.rated_current_a);
    require(p.resistance_ohm > 0.0, "resistance_ohm must be > 0", p.resistance_ohm);
    require(p.inductance_h > 0.0, "inductance_mh must be > 0", p.inductance_h);
    require(p.rotor_inertia_kgm2 > 0.0, "rotor_inertia_gcm2 must be > 0", p.rotor_inertia_kgm2);
    require(p.detent_torque_nm >= 0.0, "detent_torque_nm must be >= 0", p.detent_torque_nm);
    require(p.viscous_nm_per_rad_s >= 0.0, "viscous_nm_s_per_rad must be >= 0", p.viscous_nm_per_rad_s);
    require(p.coulomb_nm >= 0.0, "coulomb_nm must be >= 0", p.coulomb_nm);
}

double detent_energy_j(const HybridStepperParams& p, double theta_rad) {
    const double n = 4.0 * p.rotor_teeth;
    return p.detent_torque_nm / n * (1.0 - std::cos(n * theta_rad));
}

}  // namespace cnc::mech
