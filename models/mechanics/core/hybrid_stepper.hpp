// Two-phase hybrid stepper: torque and back-EMF of the two windings against the rotor angle.
//
// Rotor angle theta (shaft rad) is 0 at the DRV8825 home state, so the electrical angle of the rotor is
// psi = N_r theta + 45 deg (home = 45 deg electrical, drv8825_modes.hpp). With winding currents i_a, i_b:
//   T_em = K_m (-i_a sin psi + i_b cos psi)      e_a = -K_m omega sin psi,  e_b = K_m omega cos psi
// so sinusoidal set-points i = I (cos phi, sin phi) give T_em = K_m I sin(phi - psi): the torque-angle
// curve T_hold sin(N_r x load angle), stable where the rotor's electrical angle equals the commanded one.
// Detent (cogging) torque -T_det sin(4 N_r theta) has one period per full step.
//
// Defaults: the seed 000 motor, Wantai 42BYGHW208 (seed 000 §2.3: 1.8 deg, 12 V, 0.4 A/phase, 2,800 g cm).
// Winding 30 ohm and 37 mH per phase: Wantai's 42BYGHW208 listing (wantmotor.com, 42BYGHW series, 34 mm
// body; the same figures are quoted in the ACIS project's motor notes, github.com/mattybabaallos/ACIS/wiki/
// Motors-Information, which are those of the 0.4 A / 34 mm motor). Rotor inertia and detent torque are not
// in the sources we could find for this part: 34 g cm2 and 150 g cm are the values 42 mm x 34 mm 1.8 deg
// motors list (e.g. the 17HS13 family); set them from a measured motor if you have one.
#pragma once
#include <cmath>

namespace cnc::mech {

inline constexpr double kHomeElectricalRad = 3.14159265358979323846 / 4.0;  // DRV8825 home state, 45 deg

struct HybridStepperParams {
    int rotor_teeth = 50;                            // 1.8 deg full step = 90 electrical deg / 50 teeth
    double holding_torque_nm = 2800.0 * 9.80665e-5;  // 2,800 g cm (seed 000 §2.3), both phases at rated current
    double rated_current_a = 0.4;                    // per phase (seed 000 §2.3)
    double resistance_ohm = 30.0;                    // per phase (Wantai listing)
    double inductance_h = 0.037;                     // per phase, 37 mH (Wantai listing)
    double rotor_inertia_kgm2 = 34e-7;               // 34 g cm2 (typical of the frame; see above)
    double detent_torque_nm = 0.0147;                // 150 g cm (typical of the frame; see above)
    double viscous_nm_per_rad_s = 1e-4;  // bearing and iron-loss damping: an estimate, not a data sheet value
    double coulomb_nm = 2e-3;            // bearing friction: an estimate, not a data sheet value

    // Torque per ampere of the current vector: the holding torque is rated with both phases at the rated
    // current, a vector of sqrt(2) x I_rated.
    [[nodiscard]] double torque_constant_nm_per_a() const {
        return holding_torque_nm / (std::sqrt(2.0) * rated_current_a);
    }
    // Shaft radians per full step (pi / (2 N_r)).
    [[nodiscard]] double full_step_rad() const;
};

// Rejects values outside physics (BadInput naming the parameter).
void validate(const HybridStepperParams& p);

struct WindingCurrents {
    double a_a = 0.0;
    double b_a = 0.0;
};

// Electrical angle of the rotor, rad (psi above).
inline double rotor_electrical_rad(const HybridStepperParams& p, double theta_rad) {
    return p.rotor_teeth * theta_rad + kHomeElectricalRad;
}
// sin and cos of psi: torque, back-EMF and detent all follow from them, so the equations of motion evaluate
// one sincos per state.
struct RotorAngle {
    double sin_psi = 0.0;
    double cos_psi = 1.0;
};
inline RotorAngle rotor_angle(const HybridStepperParams& p, double theta_rad) {
    const double psi = rotor_electrical_rad(p, theta_rad);
    return {std::sin(psi), std::cos(psi)};
}
// rotor_angle for shaft angles near theta0, cheaper when called many times: psi = psi0 + N_r (theta - theta0)
// with the sine and cosine of psi0 computed once and those of the small difference rotated onto them (psi
// itself reaches hundreds of radians). Within an integration step the difference stays below a microstep
// (2.8 electrical deg at 1/32 step, 0.05 rad), where a Taylor series to d^7 / d^8 is exact to the last bit
// (truncation below 0.1^9 / 9! = 3e-15 relative at the bound) and cheaper than the libm's sincos.
class RotorAngleNear {
public:
    // `at0`: rotor_angle(p, theta0_rad), or that of a nearby RotorAngleNear (an integration step starts where
    // the last one ended, whose interpolation is within a rounding of the libm's value).
    RotorAngleNear(const HybridStepperParams& p, double theta0_rad, RotorAngle at0)
        : m_rotor_teeth(p.rotor_teeth), m_theta0_rad(theta0_rad), m_at0(at0) {}
    [[nodiscard]] RotorAngle at(double theta_rad) const {
        const double d = m_rotor_teeth * (theta_rad - m_theta0_rad);
        double s;
        double c;
        if (std::abs(d) < kSeriesBoundRad) {
            const double d2 = d * d;
            s = d * (1.0 - d2 * (1.0 / 6.0) * (1.0 - d2 * (1.0 / 20.0) * (1.0 - d2 * (1.0 / 42.0))));
            c = 1.0 - d2 * 0.5 * (1.0 - d2 * (1.0 / 12.0) * (1.0 - d2 * (1.0 / 30.0) * (1.0 - d2 * (1.0 / 56.0))));
        } else {
            s = std::sin(d);
            c = std::cos(d);
        }
        return {m_at0.sin_psi * c + m_at0.cos_psi * s, m_at0.cos_psi * c - m_at0.sin_psi * s};
    }

private:
    static constexpr double kSeriesBoundRad = 0.1;
    double m_rotor_teeth;
    double m_theta0_rad;
    RotorAngle m_at0;
};
// Electromagnetic torque of the two winding currents, N m (`km`: torque_constant_nm_per_a(), which the
// equations of motion compute once).
inline double electromagnetic_torque_nm(double km_nm_per_a, RotorAngle a, WindingCurrents i) {
    return km_nm_per_a * (-i.a_a * a.sin_psi + i.b_a * a.cos_psi);
}
// Back-EMF of the two windings at rotor speed omega, V.
inline WindingCurrents back_emf_v(double km_nm_per_a, RotorAngle a, double omega_rad_s) {
    const double k = km_nm_per_a * omega_rad_s;
    return {-k * a.sin_psi, k * a.cos_psi};
}
// Detent torque, N m: -T_det sin(4 N_r theta) = T_det sin(4 psi) (4 N_r theta = 4 psi - pi).
inline double detent_torque_nm(const HybridStepperParams& p, RotorAngle a) {
    const double s = a.sin_psi;
    const double c = a.cos_psi;
    return p.detent_torque_nm * 4.0 * s * c * (c * c - s * s);  // sin 4psi = 2 sin 2psi cos 2psi
}
// Its potential energy (zero at the detent minima).
[[nodiscard]] double detent_energy_j(const HybridStepperParams& p, double theta_rad);

}  // namespace cnc::mech
