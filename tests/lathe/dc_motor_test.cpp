// The derived motor against the seed's identified model (seed 002 §4.3): G(s) = 2.0866 / (s/74.29 + 1) from duty
// counts to motor pulses/s, and the optional second pole at -163.6.
#include <gtest/gtest.h>

#include <cmath>

#include "lathe/core/dc_motor.hpp"

namespace {

using cnc::lathe::BridgeMode;
using cnc::lathe::DcMotor;
using cnc::lathe::DcMotorParams;
using cnc::lathe::derive_motor;

constexpr double kPi = 3.14159265358979323846;
constexpr double kK = 2136.75 / 1024.0;  // §4.3: 2.0866 pulses/s per duty count

double pulses_per_s(const DcMotor& m) {
    return m.state().omega_rad_per_s * 30.0 / (2.0 * kPi);
}

// The roots of L J s^2 + (L b + R J) s + (R b + Kt^2) (§1.3.2), as positive rates, slow first.
std::pair<double, double> poles(const DcMotorParams& p) {
    const double a = p.l_h * p.j_kg_m2;
    const double b = p.l_h * p.b_nm_s_per_rad + p.r_ohm * p.j_kg_m2;
    const double c = p.r_ohm * p.b_nm_s_per_rad + p.kt_nm_per_a * p.kt_nm_per_a;
    const double d = std::sqrt(b * b - 4 * a * c);
    return {(b - d) / (2 * a), (b + d) / (2 * a)};
}

// Step response of Kt / ((L s + R)(J s + b) + Kt^2) (no zero): 1 - (p2 e^-p1 t - p1 e^-p2 t) / (p2 - p1).
double two_pole_step(double p1, double p2, double t) {
    return 1.0 - (p2 * std::exp(-p1 * t) - p1 * std::exp(-p2 * t)) / (p2 - p1);
}

TEST(DcMotor, DcGainIsTheSeedsK) {
    const DcMotorParams p = derive_motor();
    const double w_per_v = p.kt_nm_per_a / (p.r_ohm * p.b_nm_s_per_rad + p.kt_nm_per_a * p.kt_nm_per_a);
    // 22 V is duty 1024: K * 1024 pulses/s = 2136.75.
    EXPECT_NEAR(w_per_v * 22.0 * 30.0 / (2 * kPi), kK * 1024.0, 1e-9);
    EXPECT_NEAR(poles(p).first, 74.29, 1e-9);
}

TEST(DcMotor, TwoPoleOptionHasTheFittedPoles) {
    const auto [p1, p2] = poles(derive_motor(163.6));
    EXPECT_NEAR(p1, 74.29, 1e-6);
    EXPECT_NEAR(p2, 163.6, 1e-6);
}

// Full duty from rest (the tuning run of §4.3). Against G(s): the motor's electrical pole (about -5440 s^-1)
// adds a lag; the difference from the first-order response is at most p1 / (p2 - p1) = 1.38 % of the final
// speed. Against its own two-pole step response the integration must agree to 0.01 %.
TEST(DcMotor, FullDutyStepFollowsG) {
    const DcMotorParams p = derive_motor();
    const auto [p1, p2] = poles(p);
    DcMotor m(p);
    const double final_pps = kK * 1024.0;
    double t = 0.0;
    for (int k = 1; k <= 100; ++k) {  // 100 ms = 7.4 time constants
        m.advance(1e-3, BridgeMode::Drive, 22.0, 0.0);
        t += 1e-3;
        const double g = final_pps * (1.0 - std::exp(-74.29 * t));
        EXPECT_NEAR(pulses_per_s(m), g, 0.0138 * final_pps) << t;
        EXPECT_NEAR(pulses_per_s(m), final_pps * two_pole_step(p1, p2, t), 1e-4 * final_pps) << t;
    }
    EXPECT_NEAR(pulses_per_s(m), final_pps, 0.001 * final_pps);
    // The pulse count is the integral: 30 slots per revolution.
    const double expected_rev =
        final_pps / 30.0 * (t - (1.0 / p1 + 1.0 / p2)) +
        final_pps / 30.0 * (p2 * std::exp(-p1 * t) / p1 - p1 * std::exp(-p2 * t) / p2) / (p2 - p1);
    EXPECT_NEAR(m.state().angle_rad / (2 * kPi), expected_rev, 1e-3);
}

TEST(DcMotor, TwoPoleStepMatchesItsOwnResponse) {
    const DcMotorParams p = derive_motor(163.6);
    DcMotor m(p);
    const double final_pps = kK * 1024.0;
    for (int k = 1; k <= 60; ++k) {
        m.advance(1e-3, BridgeMode::Drive, 22.0, 0.0);
        EXPECT_NEAR(pulses_per_s(m), final_pps * two_pole_step(74.29, 163.6, k * 1e-3), 1e-4 * final_pps);
    }
}

// Dynamic braking from full speed: V = 0, so the speed falls as the free response of the same poles,
// w0 (p2 e^-p1 t - p1 e^-p2 t) / (p2 - p1).
TEST(DcMotor, BrakeFollowsTheFreeResponse) {
    const DcMotorParams p = derive_motor();
    const auto [p1, p2] = poles(p);
    DcMotor m(p);
    m.advance(0.2, BridgeMode::Drive, 22.0, 0.0);  // 15 time constants: steady
    const double w0 = m.state().omega_rad_per_s;
    for (int k = 1; k <= 50; ++k) {
        m.advance(1e-3, BridgeMode::Brake, 0.0, 0.0);
        EXPECT_NEAR(m.state().omega_rad_per_s, w0 * (1.0 - two_pole_step(p1, p2, k * 1e-3)), 1e-4 * w0);
    }
}

// Coasting: the current decays through the diodes into the 26 V clamp and stays 0; then only friction slows the
// shaft, with the time constant J / b.
TEST(DcMotor, CoastLetsTheCurrentDieAndTheShaftRunDown) {
    const DcMotorParams p = derive_motor();
    DcMotor m(p);
    m.advance(0.2, BridgeMode::Drive, 22.0, 0.0);
    m.advance(1e-3, BridgeMode::Coast, 0.0, 0.0);  // L i / 26 V = 31 us to reach 0
    EXPECT_EQ(m.state().current_a, 0.0);
    const double w1 = m.state().omega_rad_per_s;
    const double tau = p.j_kg_m2 / p.b_nm_s_per_rad;
    m.advance(0.02, BridgeMode::Coast, 0.0, 0.0);
    EXPECT_EQ(m.state().current_a, 0.0);
    EXPECT_NEAR(m.state().omega_rad_per_s, w1 * std::exp(-0.02 / tau), 1e-6 * w1);
}

// The electrical constants derive_motor() takes from the thesis, each seen in the motor's behaviour (seed 002
// §3.2.1, §3.2.2, §2.3): 4 A of stall current at 22 V (R = 5.5 ohm), 0.8 A drawn at full speed without load, and
// L = 1 mH of the first-order model, the current rising from rest at 22 V as V/R (1 - e^(-R t / L)) while the
// shaft has not yet turned.
TEST(DcMotor, StallNoLoadCurrentAndInductanceAreTheSeeds) {
    const DcMotorParams p = derive_motor();
    EXPECT_NEAR(22.0 / p.r_ohm, 4.0, 1e-12);
    DcMotor start(p);
    start.advance(5e-6, BridgeMode::Drive, 22.0, 0.0);
    EXPECT_NEAR(start.state().current_a, 4.0 * (1.0 - std::exp(-5.5 * 5e-6 / 1e-3)), 1e-5);
    DcMotor run(p);
    run.advance(0.2, BridgeMode::Drive, 22.0, 0.0);  // 15 time constants: steady
    EXPECT_NEAR(run.state().current_a, 0.8, 1e-5);
}

// Coasting from full speed: the current flows on through the flyback diodes into the supply, so the terminals see
// -(24 V + 2 x 1 V) (seed 002 §2.3 supply; 1N4007 datasheet forward drop near 1 A). Over 5 us the shaft keeps its
// speed, whose back-EMF is what the 22 V drove against, 22 V - R x 0.8 A: L di/dt = -26 V - R i - 17.6 V.
TEST(DcMotor, CoastingCurrentDecaysAgainstTheSupplyAndTwoDiodes) {
    const DcMotorParams p = derive_motor();
    DcMotor m(p);
    m.advance(0.2, BridgeMode::Drive, 22.0, 0.0);
    m.advance(5e-6, BridgeMode::Coast, 0.0, 0.0);
    const double r_ohm = 5.5;
    const double back_emf_v = 22.0 - r_ohm * 0.8;
    const double i_inf_a = (-(24.0 + 2.0 * 1.0) - back_emf_v) / r_ohm;
    EXPECT_NEAR(m.state().current_a, i_inf_a + (0.8 - i_inf_a) * std::exp(-r_ohm * 5e-6 / 1e-3), 1e-4);
}

}  // namespace
