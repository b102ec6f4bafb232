// Pull-out torque against the analytic holding torque and corner speed.
#include <gtest/gtest.h>

#include <cmath>

#include "mechanics/core/dynamic_axis.hpp"
#include "mechanics/core/motor_curve.hpp"

using namespace cnc::mech;

namespace {

// The seed motor at 0.2 A (R I = 6 V, half of VMOT = 12 V), so that there is a speed range where the
// driver holds the full current.
AxisParams seed_motor_at_0_2_a() {
    AxisParams p;
    p.driver.current_limit_a = 0.2;
    return p;
}

// Holding torque at the set current: K_m I = 0.2746 / (sqrt(2) 0.4) x 0.2 = 0.097087 N m.
constexpr double kHoldNm = 0.2746 / (1.4142135623730951 * 0.4) * 0.2;

// Corner speed: at the load angle of maximum torque the current is in phase with the back-EMF, so the
// winding needs |V| = |(R I + K_m w) + j N_r w L I|; it reaches VMOT when
//   (6 + 0.48543 w)^2 + (50 x 0.037 x 0.2 w)^2 = 144  ->  0.37252 w^2 + 5.8252 w - 108 = 0
//   w = 10.92 rad/s = 10.92 / (pi / 100) = 347.6 full steps/s (69.5 mm/s on a 40 mm/rev belt).
constexpr double kCornerFullStepsPerS = 347.6;

}  // namespace

TEST(MotorCurve, PullOutAtLowSpeedIsTheHoldingTorque) {
    const double t = pull_out_torque_nm(seed_motor_at_0_2_a(), 32, 10.0);
    EXPECT_NEAR(t, kHoldNm, 0.05 * kHoldNm);
}

TEST(MotorCurve, PullOutHoldsBelowAndFallsAboveTheCornerSpeed) {
    const AxisParams p = seed_motor_at_0_2_a();
    const double half = pull_out_torque_nm(p, 32, 0.5 * kCornerFullStepsPerS);
    const double twice = pull_out_torque_nm(p, 32, 2.0 * kCornerFullStepsPerS);
    const double four = pull_out_torque_nm(p, 32, 4.0 * kCornerFullStepsPerS);
    EXPECT_NEAR(half, kHoldNm, 0.05 * kHoldNm);
    EXPECT_LT(twice, 0.8 * kHoldNm);
    EXPECT_LT(four, twice);
}

TEST(MotorCurve, RequiredTorqueIsTheRailFrictionThroughThePulley) {
    // 1.5 N of rail friction on a 40 mm/rev pulley (r = 6.366 mm) plus the motor's 2e-3 N m Coulomb and
    // 1e-4 N m s/rad viscous friction at 100 full steps/s (w = pi rad/s): 9.549e-3 + 2e-3 + 3.14e-4 N m.
    const AxisParams p;
    EXPECT_NEAR(required_torque_nm(p, 100.0), 1.5 * 0.040 / (2 * 3.14159265358979) + 2e-3 + 1e-4 * 3.14159265358979,
                1e-5);
    // 3.8 kg at 1000 mm/s^2: F r = 3.8 N x 6.366 mm = 24.19e-3 N m, plus 34 g cm2 x 157.1 rad/s^2.
    EXPECT_NEAR(acceleration_torque_nm(p, 1000.0),
                3.8 * 0.040 / (2 * 3.14159265358979) + 34e-7 * 1.0 / (0.040 / (2 * 3.14159265358979)), 1e-6);
}

TEST(MotorCurve, ALeadscrewBelowFullEfficiencyAsksForMoreTorque) {
    // A Tr8 screw (8 mm lead, r = 8 mm / 2 pi) at efficiency 0.4 under a 2 kg carriage with 1.5 N of rail friction:
    // the screw turns a force F into the shaft torque F r / eta, and the carriage's inertia reflected to the shaft is
    // m r^2 / eta (the power a lossy screw needs to accelerate the carriage is the carriage's over eta).
    AxisParams p;
    p.load.kind = DriveKind::Leadscrew;
    p.load.travel_per_rev_mm = 8.0;
    p.load.carriage_mass_kg = 2.0;
    p.load.screw_efficiency = 0.4;
    const double r_m = 8e-3 / (2 * 3.14159265358979);
    const double eta = 0.4;
    const double omega = 100.0 * 2 * 3.14159265358979 / 200.0;  // 100 full steps/s of a 200-step motor
    EXPECT_NEAR(required_torque_nm(p, 100.0), 1.5 * r_m / eta + 2e-3 + 1e-4 * omega, 1e-9);
    const double accel_mm_s2 = 500.0;
    const double alpha = accel_mm_s2 * 1e-3 / r_m;
    EXPECT_NEAR(acceleration_torque_nm(p, accel_mm_s2), 34e-7 * alpha + 2.0 * r_m * r_m * alpha / eta, 1e-12);
}

TEST(MotorCurve, AStepJumpFarAboveThePullOutRateLosesWholeElectricalPeriods) {
    // Lost steps on the core alone: the seed X axis (3.8 kg) commanded from rest straight to 800 full steps/s
    // (160 mm/s), where even the steady pull-out torque (0.074 N m) is barely 5 x the rail friction's, loses
    // steps, and every slip is a whole electrical period: 4 full steps. At 50 full steps/s (10 mm/s) it
    // follows.
    const AxisParams p;
    EXPECT_FALSE(starts_without_loss(p, 32, 800.0));
    EXPECT_TRUE(starts_without_loss(p, 32, 50.0));
    DynamicAxis axis(p);
    axis.on_enable(0, true);
    const cnc::TimePs microstep_ps = cnc::kPsPerSec / (800 * 32);
    for (int k = 1; k <= 2'560; ++k) axis.on_microstep(k * microstep_ps, k, 32);
    (void)axis.shaft_angle_deg(2'560 * microstep_ps + 100 * cnc::kPsPerMs);
    ASSERT_FALSE(axis.stats().events.empty());
    EXPECT_GT(axis.stats().lost_full_steps, 0);
    EXPECT_EQ(axis.stats().lost_full_steps % 4, 0);
    for (const LostStepEvent& e : axis.stats().events) EXPECT_EQ(e.full_steps % 4, 0);
}
