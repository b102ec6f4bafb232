// JerkLimited profile on whole programs: continuous acceleration, bounded jerk, same path as trapezoidal.
#include <cmath>

#include "planner_test_util.hpp"

namespace cnc::host::planner {
namespace {

using test::config;
using test::for_each_sample;
using test::gcode;

// Max over the trajectory of |a(t+dt) - a(t)| / dt per axis (the jerk the acceleration samples show).
geom::Vec2 max_jerk(const Trajectory& t, double dt) {
    geom::Vec2 worst{};
    geom::Vec2 prev = t.at(0.0).acc_mm_per_s2;
    for_each_sample(t, dt, [&](const Sample& s) {
        worst.x_mm = std::max(worst.x_mm, std::fabs(s.acc_mm_per_s2.x_mm - prev.x_mm) / dt);
        worst.y_mm = std::max(worst.y_mm, std::fabs(s.acc_mm_per_s2.y_mm - prev.y_mm) / dt);
        prev = s.acc_mm_per_s2;
    });
    return worst;
}

const char* const kLines = "G1 X30 F6000\nG1 X60\nG1 X60 Y40\nG1 X20 Y10\nG1 X20 Y10.5\nG0 X0 Y0\n";

TEST(PlannerJerk, AccelerationContinuousAndJerkBounded) {
    for (BlendMode mode : {BlendMode::ExactStop, BlendMode::Continuous}) {
        PlannerConfig cfg = config(mode, Profile::JerkLimited);
        cfg.path_tolerance_mm = 0.0;  // corners stop: no blend arcs (their curvature steps are not jerk-limited)
        cfg.y.max_jerk_mm_per_s3 = 20000.0;
        const Trajectory t = plan(gcode(kLines, test::kRapidAboveTheAxes_mm_per_min), cfg);
        const double dt = 1e-5;
        const geom::Vec2 j = max_jerk(t, dt);
        // A step in acceleration would show as a jerk of (step / dt), far above the limits.
        EXPECT_LE(j.x_mm, 50000.0 * (1.0 + 1e-6));
        EXPECT_LE(j.y_mm, 20000.0 * (1.0 + 1e-6));
        EXPECT_GT(j.x_mm, 0.2 * 50000.0);
        for (const PlannedPiece& p : t.pieces()) {
            EXPECT_EQ(p.speed.at(0.0).a_mm_per_s2, 0.0);
            EXPECT_NEAR(p.speed.at(p.speed.duration_s()).a_mm_per_s2, 0.0, 1e-9);
        }
    }
}

TEST(PlannerJerk, SamePathAsTrapezoidalButSlower) {
    const Program p = gcode(kLines, test::kRapidAboveTheAxes_mm_per_min);
    for (BlendMode mode : {BlendMode::ExactStop, BlendMode::Continuous}) {
        const Trajectory trap = plan(p, config(mode, Profile::Trapezoidal));
        const Trajectory jerk = plan(p, config(mode, Profile::JerkLimited));
        ASSERT_EQ(trap.pieces().size(), jerk.pieces().size());
        double len_trap = 0.0;
        double len_jerk = 0.0;
        for (const PlannedPiece& x : trap.pieces()) len_trap += x.path.length_mm();
        for (const PlannedPiece& x : jerk.pieces()) len_jerk += x.path.length_mm();
        EXPECT_NEAR(len_trap, len_jerk, 1e-12);
        EXPECT_EQ(jerk.at(jerk.duration_s()).pos_mm.x_mm, 0.0);
        EXPECT_EQ(jerk.at(jerk.duration_s()).pos_mm.y_mm, 0.0);
        EXPECT_GT(jerk.duration_s(), trap.duration_s());
        // Distance covered = integral of the path speed (trapezoid rule over dense samples).
        double travelled = 0.0;
        double prev_v = 0.0;
        const double dt = 1e-5;
        for_each_sample(jerk, dt, [&](const Sample& s) {
            travelled += 0.5 * (prev_v + s.path_speed_mm_per_s) * dt;
            prev_v = s.path_speed_mm_per_s;
        });
        EXPECT_NEAR(travelled, len_jerk, 1e-3);
    }
}

TEST(PlannerJerk, LongLineTimesFromTheQuinticRule) {
    // 0 -> 100 mm/s with a = 1000, j = 50000: T = 15/8 * 100 / 1000 = 0.1875 s covering 9.375 mm, twice;
    // 81.25 mm cruise at 100 mm/s.
    const Trajectory t = plan(gcode("G1 X100 F6000\n"), config(BlendMode::ExactStop, Profile::JerkLimited));
    EXPECT_NEAR(t.duration_s(), 2 * 0.1875 + 0.8125, 1e-14);
    EXPECT_NEAR(t.at(0.1875 / 2).acc_mm_per_s2.x_mm, 1000.0, 1e-9);
    EXPECT_NEAR(t.at(0.1875).pos_mm.x_mm, 9.375, 1e-12);
}

}  // namespace
}  // namespace cnc::host::planner
