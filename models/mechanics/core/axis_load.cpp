#include "mechanics/core/axis_load.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/bad_input.hpp"

namespace cnc::mech {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinSpanM = 0.01;             // a span never gets shorter than the pulley-to-clamp distance

void require(bool ok, const char* what, double v) {
    if (!ok) throw BadInput("", std::string(what) + " (got " + std::to_string(v) + ")");
}

double dead_zone(double d, double half_width) {
    if (d > half_width) return d - half_width;
    if (d < -half_width) return d + half_width;
    return 0.0;
}

struct BeltStiffness {
    double k_n_per_m;
    double dk_dx_n_per_m2;  // 0 where a span is held at its shortest
};

// k = c/L1 + c/L2 with dL1/dx = 1, dL2/dx = -1: dk/dx = c/L2^2 - c/L1^2.
BeltStiffness belt_stiffness(const AxisLoadParams& p, double x_m) {
    const double total = p.belt_total_span_mm * 1e-3;
    const double free_l1 = p.belt_home_span_mm * 1e-3 + x_m;
    const double l1 = std::clamp(free_l1, kMinSpanM, total - kMinSpanM);
    const double l2 = total - l1;
    const double c = p.belt_specific_stiffness_n;
    return {c / l1 + c / l2, l1 == free_l1 ? c / (l2 * l2) - c / (l1 * l1) : 0.0};
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

double travel_m_per_rad(const AxisLoadParams& p) { return p.travel_per_rev_mm * 1e-3 / (2.0 * kPi); }

double belt_stiffness_n_per_m(const AxisLoadParams& p, double x_m) { return belt_stiffness(p, x_m).k_n_per_m; }

CouplingForces coupling_forces(const AxisLoadParams& p, double theta_rad, double omega_rad_s, double x_m,
                               double v_m_s) {
    const double r = travel_m_per_rad(p);
    const double stretch = r * theta_rad - x_m;
    const double stretch_rate = r * omega_rad_s - v_m_s;
    if (p.kind == DriveKind::Belt) {
        const BeltStiffness k = belt_stiffness(p, x_m);
        const double c = 2.0 * p.belt_damping_ratio * std::sqrt(k.k_n_per_m * p.carriage_mass_kg);
        const double spring = k.k_n_per_m * stretch + c * stretch_rate;
        return {spring - 0.5 * k.dk_dx_n_per_m2 * stretch * stretch, -spring * r};
    }
    if (p.kind == DriveKind::Leadscrew) {
        const double engaged = dead_zone(stretch, 0.5 * p.backlash_mm * 1e-3);
        if (engaged == 0.0) return {};
        const double c = 2.0 * p.screw_damping_ratio * std::sqrt(p.screw_stiffness_n_per_m * p.carriage_mass_kg);
        const double force = p.screw_stiffness_n_per_m * engaged + c * stretch_rate;
        return {force, -force * r / p.screw_efficiency};
    }
    return {};
}

double rail_friction_n(const AxisLoadParams& p, double v_m_s, double other_n, FrictionMode mode) {
    const double viscous = -p.rail_viscous_n_per_m_s * v_m_s;
    return viscous + coulomb_friction(mode, p.rail_friction_n, v_m_s, other_n + viscous, p.carriage_mass_kg);
}

double rail_friction_n(const AxisLoadParams& p, double v_m_s, double other_n) {
    return rail_friction_n(p, v_m_s, other_n, friction_mode(v_m_s, kRailStickBandM_s));
}

double coupling_energy_j(const AxisLoadParams& p, double theta_rad, double x_m) {
    const double stretch = travel_m_per_rad(p) * theta_rad - x_m;
    if (p.kind == DriveKind::Belt) return 0.5 * belt_stiffness_n_per_m(p, x_m) * stretch * stretch;
    if (p.kind == DriveKind::Leadscrew) {
        const double engaged = dead_zone(stretch, 0.5 * p.backlash_mm * 1e-3);
        return 0.5 * p.screw_stiffness_n_per_m * engaged * engaged;
    }
    return 0.0;
}

}  // namespace cnc::mech
