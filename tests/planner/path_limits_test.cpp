// path_limits, the projection of the per-axis limits onto the path (seed 004 §3.2: limits are per joint), with
// LinuxCNC's split of an arc's acceleration budget (blendmath.h BLEND_ACC_RATIO_TANGENTIAL 0.5, normal
// sqrt(1 - 0.5^2) = sqrt(3)/2; tc.c tcUpdateCircleAccRatio / blendmath.c pmCircleActualMaxVel for a circle with a
// move queued after it). Expected values are worked out here from those rules, directly on the pure function.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "host/core/planner/curve.hpp"
#include "host/core/planner/path_limits.hpp"
#include "host/core/planner/planner_config.hpp"

namespace cnc::host::planner {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNoFeedCap = std::numeric_limits<double>::infinity();

PlannerConfig axes(double v_mm_s, double a_mm_s2, double j_mm_s3) {
    PlannerConfig cfg;
    cfg.x = {v_mm_s, a_mm_s2, j_mm_s3};
    cfg.y = {v_mm_s, a_mm_s2, j_mm_s3};
    return cfg;
}

TEST(PathLimits, A45DegreeLineGoesSqrt2TimesTheAxisLimits) {
    // Each axis carries cos 45 of the path: limit / cos 45 = sqrt(2) x limit, for speed, acceleration and jerk.
    const PathLimits l = path_limits(Curve::line({0, 0}, {10, 10}), kNoFeedCap, axes(100, 1000, 50'000), false);
    EXPECT_NEAR(l.velocity_mm_per_s, 100 * std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(l.accel_mm_per_s2, 1000 * std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(l.jerk_mm_per_s3, 50'000 * std::sqrt(2.0), 1e-6);
    // Negative direction, 30 deg below -x, X at 100 mm/s and Y at 40 mm/s: min(100 / cos 30, 40 / sin 30) = 80.
    PlannerConfig cfg = axes(100, 1000, 50'000);
    cfg.y.max_velocity_mm_per_s = 40;
    const PathLimits m =
        path_limits(Curve::line({0, 0}, {-10 * std::cos(kPi / 6), -10 * std::sin(kPi / 6)}), 1e9, cfg, false);
    EXPECT_NEAR(m.velocity_mm_per_s, 80.0, 1e-9);
    // The programmed feed caps the speed, not the acceleration.
    const PathLimits f = path_limits(Curve::line({0, 0}, {10, 0}), 20.0, axes(100, 1000, 50'000), false);
    EXPECT_DOUBLE_EQ(f.velocity_mm_per_s, 20.0);
    EXPECT_DOUBLE_EQ(f.accel_mm_per_s2, 1000.0);
}

TEST(PathLimits, ACircleSplitsItsAccelerationHalfTangentialAndSqrt3Over2Centripetal) {
    // Quarter circle R = 10 mm, A = 1000 mm/s^2: tangential A/2 = 500; speed cap sqrt((sqrt(3)/2) A R) = 93.06 mm/s
    // (below the 100 mm/s axis limit).
    const Curve arc = Curve::arc({10, 0}, {0, 10}, {0, 0}, kPi / 2);
    const PathLimits l = path_limits(arc, kNoFeedCap, axes(100, 1000, 50'000), false);
    EXPECT_NEAR(l.accel_mm_per_s2, 500.0, 1e-9);
    EXPECT_NEAR(l.velocity_mm_per_s, std::sqrt(std::sqrt(3.0) / 2 * 1000 * 10), 1e-9);
    EXPECT_NEAR(l.jerk_mm_per_s3, 50'000.0, 1e-6);
    // Clockwise (negative sweep) is the same.
    const PathLimits cw = path_limits(Curve::arc({10, 0}, {0, -10}, {0, 0}, -kPi / 2), kNoFeedCap,
                                      axes(100, 1000, 50'000), false);
    EXPECT_NEAR(cw.accel_mm_per_s2, 500.0, 1e-9);
    EXPECT_NEAR(cw.velocity_mm_per_s, l.velocity_mm_per_s, 1e-9);
}

TEST(PathLimits, AFinalizedCircleBelowItsCentripetalLimitKeepsTheRestForTheTangent) {
    // Axis speed 50 mm/s on R = 10 mm at A = 1000: centripetal V^2 / R = 250 = 0.25 A < (sqrt(3)/2) A, so the
    // tangent may use sqrt(1 - 0.25^2) A = 968.25 mm/s^2 once a move is queued after the circle; not before.
    const Curve arc = Curve::arc({10, 0}, {0, 10}, {0, 0}, kPi / 2);
    const PathLimits queued = path_limits(arc, kNoFeedCap, axes(50, 1000, 50'000), true);
    EXPECT_NEAR(queued.accel_mm_per_s2, std::sqrt(1 - 0.25 * 0.25) * 1000, 1e-9);
    EXPECT_NEAR(queued.velocity_mm_per_s, 50.0, 1e-12);
    EXPECT_NEAR(path_limits(arc, kNoFeedCap, axes(50, 1000, 50'000), false).accel_mm_per_s2, 500.0, 1e-9);
    // At 95 mm/s the centripetal share would be 0.9025 A, above sqrt(3)/2: back to A/2.
    EXPECT_NEAR(path_limits(arc, kNoFeedCap, axes(95, 1000, 50'000), true).accel_mm_per_s2, 500.0, 1e-9);
}

TEST(PathLimits, ASpiralGivesHalfTheBudgetToEachPart) {
    // An arc whose end lies 0.005 mm off the start circle (within the interpreter's 0.01 mm) is a spiral: its
    // tangential and normal accelerations are not orthogonal, so each gets A/2 (triangle inequality), even with a
    // move queued after it. Checked against the curve's own bounds of stretch and curvature.
    const Curve spiral = Curve::arc({10, 0}, {0, 10.005}, {0, 0}, kPi / 2);
    ASSERT_NE(spiral.start_radius_mm(), spiral.end_radius_mm());
    const PathLimits l = path_limits(spiral, kNoFeedCap, axes(50, 1000, 50'000), true);
    EXPECT_NEAR(l.accel_mm_per_s2 * spiral.max_stretch(), 500.0, 1e-9);
    const PathLimits fast = path_limits(spiral, kNoFeedCap, axes(1000, 1000, 50'000), false);
    EXPECT_NEAR(fast.velocity_mm_per_s * fast.velocity_mm_per_s * spiral.max_curvature_per_mm(), 500.0, 1e-9);
}

}  // namespace
}  // namespace cnc::host::planner
