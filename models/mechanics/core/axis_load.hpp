// What the motor drives: a carriage on rails, coupled to the shaft by a GT2 belt or a leadscrew.
//
// Belt: the carriage sits between two belt spans (motor pulley -> carriage -> idler). Each span is a spring
// of stiffness c_sp / length (c_sp = E A, the belt's specific stiffness per unit strain), and the two act in
// parallel, so k(x) = c_sp / L1 + c_sp / L2 with L1 = home span + x and L2 = total - L1: the belt is
// stiffest near either end. The belt stores U = k(x) (s - x)^2 / 2, s = pulley travel, and the forces are
// its gradient (so the model conserves energy exactly; the term from dk/dx is tiny at belt stretches of um).
// Damping: a ratio of the critical damping of the carriage on the belt, 2 zeta sqrt(k m).
// Leadscrew: the nut follows the screw travel s with axial play (backlash) b: no force within +-b/2, then
// an axial spring (screw and nut stiffness) with damping. The screw's efficiency divides the torque the
// motor must supply (we assume the motor always drives the load, i.e. the screw never back-drives it).
// Rails: Coulomb friction that sticks at rest (friction.hpp) and viscous friction.
#pragma once
#include <algorithm>
#include <cmath>

#include "mechanics/core/friction.hpp"

namespace cnc::mech {

enum class DriveKind { Free, Belt, Leadscrew };  // Free: the rotor alone (no carriage attached)

struct AxisLoadParams {
    DriveKind kind = DriveKind::Belt;
    double travel_per_rev_mm = 40.0;  // GT2 x 20 teeth (seed 000 §3.4.2) or the screw lead
    double carriage_mass_kg = 3.8;    // seed 000 §2.3: the X motor moves 3.8 kg
    double rail_friction_n = 1.5;     // linear bearings on rods, about 0.04 x m g: an estimate
    double rail_viscous_n_per_m_s = 0.0;
    // Belt
    double belt_specific_stiffness_n = 20'000.0;  // c_sp of a 6 mm glass-fibre GT2 belt, order of maker tables
    double belt_total_span_mm = 560.0;            // both free spans together (seed 000 §7.1.2: 460 mm travel + ends)
    double belt_home_span_mm = 50.0;              // span from pulley to carriage at carriage 0 mm
    double belt_damping_ratio = 0.05;             // of critical: reinforced rubber belts, a few per cent
    // Leadscrew
    double screw_efficiency = 0.4;  // trapezoidal (Tr8) screw with a plastic or bronze nut
    double backlash_mm = 0.05;
    double screw_stiffness_n_per_m = 5e7;  // axial stiffness of screw and nut
    double screw_damping_ratio = 0.1;
};

void validate(const AxisLoadParams& p);

// Metres of carriage travel per shaft radian.
[[nodiscard]] double travel_m_per_rad(const AxisLoadParams& p);

struct CouplingForces {
    double on_carriage_n = 0.0;  // force on the carriage, +x
    double on_rotor_nm = 0.0;    // torque the coupling puts on the shaft
};

// The belt or screw between shaft and carriage, with what follows from its parameters computed once: the
// equations of motion evaluate its forces at every stage of every integration step.
class Coupling {
public:
    explicit Coupling(const AxisLoadParams& p);

    // Forces between shaft (angle theta, speed omega) and carriage (x, v).
    [[nodiscard]] CouplingForces forces(double theta_rad, double omega_rad_s, double x_m, double v_m_s) const {
        const double stretch = m_travel_m_per_rad * theta_rad - x_m;
        const double stretch_rate = m_travel_m_per_rad * omega_rad_s - v_m_s;
        if (m_kind == DriveKind::Belt) {
            const BeltStiffness k = belt_stiffness(x_m);
            const double spring = k.k_n_per_m * stretch + m_damping_per_sqrt_k * std::sqrt(k.k_n_per_m) * stretch_rate;
            return {spring - 0.5 * k.dk_dx_n_per_m2 * stretch * stretch, -spring * m_travel_m_per_rad};
        }
        if (m_kind == DriveKind::Leadscrew) {
            const double engaged = dead_zone(stretch);
            if (engaged == 0.0) return {};
            const double force = m_screw_stiffness_n_per_m * engaged + m_screw_damping_n_s_per_m * stretch_rate;
            return {force, -force * m_screw_torque_per_n};
        }
        return {};
    }
    // Belt stiffness at carriage position x (m from 0).
    [[nodiscard]] double belt_stiffness_n_per_m(double x_m) const { return belt_stiffness(x_m).k_n_per_m; }
    // Energy stored in the coupling, J.
    [[nodiscard]] double energy_j(double theta_rad, double x_m) const;

private:
    struct BeltStiffness {
        double k_n_per_m;
        double dk_dx_n_per_m2;  // 0 where a span is held at its shortest
    };
    // k = c/L1 + c/L2 = c (L1 + L2) / (L1 L2) with dL1/dx = 1, dL2/dx = -1:
    // dk/dx = c/L2^2 - c/L1^2 = c (L1 + L2)(L1 - L2) / (L1 L2)^2 (one division: they run at every stage).
    [[nodiscard]] BeltStiffness belt_stiffness(double x_m) const {
        const double free_l1 = m_home_span_m + x_m;
        const double l1 = std::clamp(free_l1, kMinSpanM, m_total_span_m - kMinSpanM);
        const double l2 = m_total_span_m - l1;
        const double inv_l1_l2 = 1.0 / (l1 * l2);
        const double k = m_specific_stiffness_n * (l1 + l2) * inv_l1_l2;
        return {k, l1 == free_l1 ? k * (l1 - l2) * inv_l1_l2 : 0.0};
    }
    // The screw's travel beyond the backlash either way (0 within it).
    [[nodiscard]] double dead_zone(double d) const {
        if (d > m_half_backlash_m) return d - m_half_backlash_m;
        if (d < -m_half_backlash_m) return d + m_half_backlash_m;
        return 0.0;
    }

    static constexpr double kMinSpanM = 0.01;  // a span never gets shorter than the pulley-to-clamp distance
    DriveKind m_kind;
    double m_travel_m_per_rad;
    double m_home_span_m;
    double m_total_span_m;
    double m_specific_stiffness_n;
    double m_damping_per_sqrt_k;  // the belt's damping 2 zeta sqrt(k m) over sqrt(k)
    double m_half_backlash_m;
    double m_screw_stiffness_n_per_m;
    double m_screw_damping_n_s_per_m;
    double m_screw_torque_per_n;  // travel per radian over the screw's efficiency
};
// The carriage may stick below 0.1 mm/s (friction.hpp).
inline constexpr double kRailStickBandM_s = 1e-4;
// Rail friction force on the carriage at speed v (opposes it), N; `other_n`: the other forces on it; `mode`:
// the carriage's side of the stick band, friction_mode(v, kRailStickBandM_s) unless the integrator holds it.
[[nodiscard]] double rail_friction_n(const AxisLoadParams& p, double v_m_s, double other_n, FrictionMode mode);
[[nodiscard]] double rail_friction_n(const AxisLoadParams& p, double v_m_s, double other_n);

}  // namespace cnc::mech
