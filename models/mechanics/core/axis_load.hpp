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
#include "mechanics/core/friction.hpp"

namespace cnc::mech {

enum class DriveKind { Free, Belt, Leadscrew };  // Free: the rotor alone (no carriage attached)

struct AxisLoadParams {
    DriveKind kind = DriveKind::Belt;
    double travel_per_rev_mm = 40.0;      // GT2 x 20 teeth (seed 000 §2.2) or the screw lead
    double carriage_mass_kg = 3.8;        // seed 000 §8: the X motor moves 3.8 kg
    double rail_friction_n = 1.5;         // linear bearings on rods, about 0.04 x m g: an estimate
    double rail_viscous_n_per_m_s = 0.0;
    // Belt
    double belt_specific_stiffness_n = 20'000.0;  // c_sp of a 6 mm glass-fibre GT2 belt, order of maker tables
    double belt_total_span_mm = 560.0;    // both free spans together (seed 000 §7.1.2: 460 mm travel + ends)
    double belt_home_span_mm = 50.0;      // span from pulley to carriage at carriage 0 mm
    double belt_damping_ratio = 0.05;     // of critical: reinforced rubber belts, a few per cent
    // Leadscrew
    double screw_efficiency = 0.4;        // trapezoidal (Tr8) screw with a plastic or bronze nut
    double backlash_mm = 0.05;
    double screw_stiffness_n_per_m = 5e7; // axial stiffness of screw and nut
    double screw_damping_ratio = 0.1;
};

void validate(const AxisLoadParams& p);

// Metres of carriage travel per shaft radian.
[[nodiscard]] double travel_m_per_rad(const AxisLoadParams& p);
// Belt stiffness at carriage position x (m from 0).
[[nodiscard]] double belt_stiffness_n_per_m(const AxisLoadParams& p, double x_m);

struct CouplingForces {
    double on_carriage_n = 0.0;  // force on the carriage, +x
    double on_rotor_nm = 0.0;    // torque the coupling puts on the shaft
};

// Forces between shaft (angle theta, speed omega) and carriage (x, v).
[[nodiscard]] CouplingForces coupling_forces(const AxisLoadParams& p, double theta_rad, double omega_rad_s,
                                             double x_m, double v_m_s);
// The carriage may stick below 0.1 mm/s (friction.hpp).
inline constexpr double kRailStickBandM_s = 1e-4;
// Rail friction force on the carriage at speed v (opposes it), N; `other_n`: the other forces on it; `mode`:
// the carriage's side of the stick band, friction_mode(v, kRailStickBandM_s) unless the integrator holds it.
[[nodiscard]] double rail_friction_n(const AxisLoadParams& p, double v_m_s, double other_n, FrictionMode mode);
[[nodiscard]] double rail_friction_n(const AxisLoadParams& p, double v_m_s, double other_n);
// Energy stored in the coupling, J.
[[nodiscard]] double coupling_energy_j(const AxisLoadParams& p, double theta_rad, double x_m);

}  // namespace cnc::mech
