#include "mechanics/core/axis_load.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/bad_input.hpp"
#include "common/math_constants.hpp"

namespace cnc::mech {

namespace {

void require(bool ok, const char* what, double v) {
    if (!ok) throw BadInput("", std::string(what) + " (got " + std::to_string(v) + ")");
}

}  // namespace

void validate(const AxisLoadParams& p) {
    require(p.travel_per_rev_mm > 0.0, "travel per motor revolution must be > 0 mm", p.travel_per_rev_mm);
    if (p.kind == DriveKind::Free) return;
    require(p.carriage_mass_kg > 0.0, "carriage_mass_kg must be > 0", p.carriage_mass_kg);
    require(p.rail_friction_n >= 0.0, "rail_friction_n must be >= 0", p.rail_friction_n);
    require(p.rail_viscous_n_per_m_s >= 0.0, "rail_viscous_n_s_per_m must be >= 0", p.rail_viscous_n_per_m_s);
    if (p.kind == DriveKind::Belt) {
        require(p.belt_specific_stiffness_n > 0.0, "belt_specific_stiffness_n must be > 0",
                p.belt_specific_stiffness_n);
        require(p.belt_home_span_mm > 0.0, "belt_home_span_mm must be > 0", p.belt_home_span_mm);
        require(p.belt_total_span_mm > p.belt_home_span_mm, "belt_total_span_mm must exceed belt_home_span_mm",
                p.belt_total_span_mm);
        require(p.belt_damping_ratio >= 0.0, "belt_damping_ratio must be >= 0", p.belt_damping_ratio);
    } else {
        require(p.screw_efficiency > 0.0 && p.screw_efficiency <= 1.0, "screw_efficiency must be in (0, 1]",
                p.screw_efficiency);
        require(p.backlash_mm >= 0.0, "backlash_mm must be >= 0", p.backlash_mm);
        require(p.screw_stiffness_n_per_m > 0.0, "screw_stiffness_n_per_m must be > 0", p.screw_stiffness_n_per_m);
        require(p.screw_damping_ratio >= 0.0, "screw_damping_ratio must be >= 0", p.screw_damping_ratio);
    }
}

double travel_m_per_rad(const AxisLoadParams& p) {
    return p.travel_per_rev_mm * 1e-3 / (2.0 * kPi);
}

Coupling::Coupling(const AxisLoadParams& p)
    : m_kind(p.kind),
      m_travel_m_per_rad(travel_m_per_rad(p)),
      m_home_span_m(p.belt_home_span_mm * 1e-3),
      m_total_span_m(p.belt_total_span_mm * 1e-3),
      m_specific_stiffness_n(p.belt_specific_stiffness_n),
      m_damping_per_sqrt_k(2.0 * p.belt_damping_ratio * std::sqrt(p.carriage_mass_kg)),
      m_half_backlash_m(0.5 * p.backlash_mm * 1e-3),
      m_screw_stiffness_n_per_m(p.screw_stiffness_n_per_m),
      m_screw_damping_n_s_per_m(2.0 * p.screw_damping_ratio *
                                std::sqrt(p.screw_stiffness_n_per_m * p.carriage_mass_kg)),
      m_screw_torque_per_n(m_travel_m_per_rad / p.screw_efficiency) {}

double Coupling::energy_j(double theta_rad, double x_m) const {
    const double stretch = m_travel_m_per_rad * theta_rad - x_m;
    if (m_kind == DriveKind::Belt) return 0.5 * belt_stiffness_n_per_m(x_m) * stretch * stretch;
    if (m_kind == DriveKind::Leadscrew) {
        const double engaged = dead_zone(stretch);
        return 0.5 * m_screw_stiffness_n_per_m * engaged * engaged;
    }
    return 0.0;
}

double rail_friction_n(const AxisLoadParams& p, double v_m_s, double other_n, FrictionMode mode) {
    const double viscous = -p.rail_viscous_n_per_m_s * v_m_s;
    return viscous + coulomb_friction(mode, p.rail_friction_n, v_m_s, other_n + viscous, p.carriage_mass_kg);
}

double rail_friction_n(const AxisLoadParams& p, double v_m_s, double other_n) {
    return rail_friction_n(p, v_m_s, other_n, friction_mode(v_m_s, kRailStickBandM_s));
}

}  // namespace cnc::mech
