// Speed-change math of both profiles (speed_profile.hpp) and the look-ahead window.
#include <cmath>

#include "host/core/planner/lookahead.hpp"
#include "host/core/planner/speed_profile.hpp"
#include "planner_test_util.hpp"

namespace cnc::host::planner {
namespace {

constexpr PathLimits kLimits{100.0, 1000.0, 50000.0};

TEST(PlannerProfile, TrapezoidTransition) {
    EXPECT_DOUBLE_EQ(transition_time_s(Profile::Trapezoidal, 20.0, 70.0, kLimits), 0.05);
    EXPECT_DOUBLE_EQ(transition_distance_mm(Profile::Trapezoidal, 20.0, 70.0, kLimits), 2.25);
    EXPECT_DOUBLE_EQ(reachable_speed(Profile::Trapezoidal, 20.0, 2.25, kLimits), 70.0);
}

TEST(PlannerProfile, QuinticTimeIsSetByAccelOrJerk) {
    // 15/8 * 100 / 1000 = 0.1875 s > sqrt(10/sqrt(3) * 100 / 50000) = 0.1075 s: acceleration-bound.
    EXPECT_NEAR(transition_time_s(Profile::JerkLimited, 0.0, 100.0, kLimits), 0.1875, 1e-15);
    // With j = 5000: sqrt(10/sqrt(3) * 100 / 5000) = 0.339809 s: jerk-bound.
    const PathLimits soft{100.0, 1000.0, 5000.0};
    EXPECT_NEAR(transition_time_s(Profile::JerkLimited, 100.0, 0.0, soft), std::sqrt(0.2 / std::sqrt(3.0)), 1e-15);
}

TEST(PlannerProfile, ReachableSpeedInvertsTheDistanceOnBothBranches) {
    for (const PathLimits& lim : {kLimits, PathLimits{100.0, 1000.0, 5000.0}, PathLimits{100.0, 50.0, 1e6}}) {
        for (double v0 : {0.0, 3.0, 40.0}) {
            for (double d : {1e-6, 0.01, 0.5, 3.0, 40.0}) {
                const double v1 = reachable_speed(Profile::JerkLimited, v0, d, lim);
                EXPECT_GE(v1, v0);
                // v1 - v0 inside transition_distance_mm keeps only the digits of dv above v0's last bit: with
                // v0 = 40 and d = 1e-6 mm, dv ~ 5e-13 is known to ~1 %, i.e. d to ~1e-9 mm.
                EXPECT_NEAR(transition_distance_mm(Profile::JerkLimited, v0, v1, lim), d, 1e-8 + 1e-12 * d);
            }
        }
    }
}

// Samples a profile densely; returns {max |a|, max |jerk|} (jerk from the difference of analytic accelerations).
std::pair<double, double> peaks(const SpeedProfile& sp) {
    const int n = 200000;
    const double dt = sp.duration_s() / n;
    double a_max = 0.0;
    double j_max = 0.0;
    double a_prev = sp.at(0.0).a_mm_per_s2;
    for (int i = 1; i <= n; ++i) {
        const double a = sp.at(i * dt).a_mm_per_s2;
        a_max = std::max(a_max, std::fabs(a));
        j_max = std::max(j_max, std::fabs(a - a_prev) / dt);
        a_prev = a;
    }
    return {a_max, j_max};
}

TEST(PlannerProfile, QuinticPeaksMeetTheLimits) {
    // Accel-bound rise 0 -> 100: the peak acceleration is exactly a (at tau = 1/2), the jerk
    // 10/sqrt(3) dv / T^2 below j.
    const SpeedProfile fast = make_speed_profile(Profile::JerkLimited, 100.0, 0.0, 0.0, kLimits);
    EXPECT_DOUBLE_EQ(fast.peak_mm_per_s, 100.0);
    const auto [a1, j1] = peaks(fast);
    EXPECT_NEAR(a1, 1000.0, 1e-5);
    EXPECT_LE(a1, 1000.0 * (1.0 + 1e-12));
    EXPECT_NEAR(j1, 10.0 / std::sqrt(3.0) * 100.0 / (0.1875 * 0.1875), 1e-2);  // 16421.6 < 50000
    // Jerk-bound: the peak jerk is exactly j (numerically within 1e-4), acceleration 15/8 * 100 / T.
    const PathLimits soft{100.0, 1000.0, 5000.0};
    const SpeedProfile slow = make_speed_profile(Profile::JerkLimited, 100.0, 0.0, 0.0, soft);
    const auto [a2, j2] = peaks(slow);
    EXPECT_NEAR(a2, 15.0 / 8.0 * 100.0 / std::sqrt(0.2 / std::sqrt(3.0)), 1e-6);
    EXPECT_NEAR(j2, 5000.0, 5000.0 * 1e-4);
    EXPECT_LE(j2, 5000.0 * (1.0 + 1e-9));
}

TEST(PlannerProfile, ProfileCoversItsLengthExactly) {
    for (Profile shape : {Profile::Trapezoidal, Profile::JerkLimited}) {
        for (double len : {0.001, 0.7, 8.0, 250.0}) {
            const SpeedProfile sp = make_speed_profile(shape, len, 0.0, 0.0, kLimits);
            EXPECT_NEAR(sp.at(sp.duration_s()).s_mm, len, 1e-12);
            EXPECT_NEAR(sp.at(sp.duration_s() * (1.0 - 1e-12)).s_mm, len, 1e-9);
            EXPECT_LE(sp.peak_mm_per_s, 100.0);
        }
    }
}

TEST(PlannerLookahead, WindowOfThreeMovesCapsTheSpeed) {
    // Ten 1 mm colinear pieces. While piece k runs the planner knows k..k+2, so piece k must end at a speed
    // from which the machine stops within the 2 mm left: sqrt(2 a 2 mm) = 63.25 mm/s.
    std::vector<LookaheadPiece> pieces;
    for (int i = 0; i < 10; ++i) pieces.push_back(LookaheadPiece{1.0, kLimits, i == 0 ? 0.0 : 100.0, i});
    const std::vector<double> v = boundary_speeds(pieces, Profile::Trapezoidal, 3);
    ASSERT_EQ(v.size(), 11u);
    EXPECT_DOUBLE_EQ(v[0], 0.0);
    EXPECT_NEAR(v[1], std::sqrt(2000.0), 1e-12);
    for (int k = 2; k <= 8; ++k) EXPECT_NEAR(v[k], std::sqrt(4000.0), 1e-12) << k;
    EXPECT_NEAR(v[9], std::sqrt(2000.0), 1e-12);
    EXPECT_DOUBLE_EQ(v[10], 0.0);
    const std::vector<double> one = boundary_speeds(pieces, Profile::Trapezoidal, 1);
    for (double s : one) EXPECT_DOUBLE_EQ(s, 0.0);
    const std::vector<double> all = boundary_speeds(pieces, Profile::Trapezoidal, 32);
    EXPECT_NEAR(all[5], 100.0, 1e-12);  // 5 mm to accelerate and 5 to stop: exactly 100 at the middle
    EXPECT_NEAR(all[3], std::sqrt(6000.0), 1e-12);
}

}  // namespace
}  // namespace cnc::host::planner
