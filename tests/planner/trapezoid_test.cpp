// Single moves with the trapezoidal profile: exact phase times, per-axis caps, rapids.
#include <cmath>

#include "planner_test_util.hpp"

namespace cnc::host::planner {
namespace {

using test::config;
using test::gcode;

// The profile's arithmetic, in exact stop (G61.1), where a single move has the whole acceleration: in G64 the
// program's last move has half of it (continuous_test.cpp, LastMoveAtHalfTheAcceleration).
TEST(PlannerTrapezoid, LongLineExactTimes) {
    // F6000 = 100 mm/s, a = 1000: accelerate v/a = 0.1 s over v^2/2a = 5 mm, cruise 90 mm in 0.9 s, brake 0.1 s.
    const Trajectory t = plan(gcode("G1 X100 F6000\n"), config(BlendMode::ExactStop));
    ASSERT_EQ(t.pieces().size(), 1u);
    const SpeedProfile& sp = t.pieces()[0].speed;
    EXPECT_DOUBLE_EQ(sp.peak_mm_per_s, 100.0);
    EXPECT_NEAR(sp.rise_s, 0.1, 1e-15);
    EXPECT_NEAR(sp.cruise_s, 0.9, 1e-14);
    EXPECT_NEAR(sp.fall_s, 0.1, 1e-15);
    EXPECT_NEAR(t.duration_s(), 1.1, 1e-14);
    EXPECT_NEAR(t.at(0.1).pos_mm.x_mm, 5.0, 1e-12);
    EXPECT_NEAR(t.at(0.05).pos_mm.x_mm, 1.25, 1e-12);
    EXPECT_NEAR(t.at(0.05).acc_mm_per_s2.x_mm, 1000.0, 1e-9);
    EXPECT_NEAR(t.at(0.55).pos_mm.x_mm, 50.0, 1e-12);
    EXPECT_NEAR(t.at(0.55).vel_mm_per_s.x_mm, 100.0, 1e-12);
    EXPECT_NEAR(t.at(1.05).acc_mm_per_s2.x_mm, -1000.0, 1e-9);
    EXPECT_EQ(t.at(1.1).pos_mm.x_mm, 100.0);
    EXPECT_EQ(t.at(5.0).path_speed_mm_per_s, 0.0);
    EXPECT_EQ(t.at(0.3).move, 0);
}

TEST(PlannerTrapezoid, ShortLineIsATriangle) {
    // 2 mm cannot reach 100 mm/s: peak sqrt(a L) = 44.72 mm/s, total 2 sqrt(L/a) = 89.44 ms.
    const Trajectory t = plan(gcode("G1 X2 F6000\n"), config(BlendMode::ExactStop));
    const SpeedProfile& sp = t.pieces()[0].speed;
    EXPECT_NEAR(sp.peak_mm_per_s, std::sqrt(2000.0), 1e-12);
    EXPECT_EQ(sp.cruise_s, 0.0);
    EXPECT_NEAR(t.duration_s(), 2.0 * std::sqrt(0.002), 1e-15);
    EXPECT_NEAR(t.at(std::sqrt(0.002)).pos_mm.x_mm, 1.0, 1e-12);
}

TEST(PlannerTrapezoid, DiagonalMayExceedTheAxisLimitsAlongThePath) {
    // 45 deg with equal axes: each axis gets v cos45, so the path may go sqrt(2) * 100 mm/s and sqrt(2) * 1000 mm/s^2.
    const Trajectory t = plan(gcode("G1 X300 Y300 F60000\n"), config(BlendMode::ExactStop));
    const SpeedProfile& sp = t.pieces()[0].speed;
    EXPECT_NEAR(sp.limits.velocity_mm_per_s, 100.0 * std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(sp.limits.accel_mm_per_s2, 1000.0 * std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(sp.peak_mm_per_s, 100.0 * std::sqrt(2.0), 1e-12);
    const Sample mid = t.at(0.5 * t.duration_s());
    EXPECT_NEAR(mid.vel_mm_per_s.x_mm, 100.0, 1e-9);
    EXPECT_NEAR(mid.vel_mm_per_s.y_mm, 100.0, 1e-9);
    EXPECT_NEAR(t.at(0.01).acc_mm_per_s2.y_mm, 1000.0, 1e-9);
}

TEST(PlannerTrapezoid, UnequalAxesTheTighterOneWins) {
    // Direction (0.6, 0.8): v <= min(100/0.6, 50/0.8) = 62.5, a <= min(1000/0.6, 400/0.8) = 500.
    PlannerConfig cfg = config(BlendMode::ExactStop);
    cfg.y.max_velocity_mm_per_s = 50.0;
    cfg.y.max_accel_mm_per_s2 = 400.0;
    const Trajectory t = plan(gcode("G1 X300 Y400 F60000\n"), cfg);
    const PathLimits& lim = t.pieces()[0].speed.limits;
    EXPECT_NEAR(lim.velocity_mm_per_s, 62.5, 1e-12);
    EXPECT_NEAR(lim.accel_mm_per_s2, 500.0, 1e-12);
    EXPECT_NEAR(t.at(0.5 * t.duration_s()).vel_mm_per_s.y_mm, 50.0, 1e-9);
}

TEST(PlannerTrapezoid, FeedBelowTheAxisLimit) {
    const Trajectory t = plan(gcode("G1 X50 F1200\n"), config(BlendMode::ExactStop));
    EXPECT_DOUBLE_EQ(t.pieces()[0].speed.peak_mm_per_s, 20.0);  // 1200 mm/min
    EXPECT_NEAR(t.duration_s(), 50.0 / 20.0 + 20.0 / 1000.0, 1e-14);
}

TEST(PlannerTrapezoid, RapidRunsAtTheMachineRapidSpeed) {
    // G0 goes at the program's rapid feed (machine.rapid_feed_mm_per_min: 1200 mm/min = 20 mm/s) as its path
    // speed, capped by the axes: 40 mm/s at 2400 mm/min; above the 100 mm/s axis limits, 100 mm/s on one axis and
    // 100 sqrt(2) mm/s on the diagonal (each axis at its limit).
    EXPECT_DOUBLE_EQ(plan(gcode("G0 X200\n"), config(BlendMode::Continuous)).pieces()[0].speed.peak_mm_per_s, 20.0);
    EXPECT_DOUBLE_EQ(plan(gcode("G0 X200\n", 2400.0), config(BlendMode::Continuous)).pieces()[0].speed.peak_mm_per_s,
                     40.0);
    const double fast = test::kRapidAboveTheAxes_mm_per_min;
    EXPECT_DOUBLE_EQ(plan(gcode("G0 X200\n", fast), config(BlendMode::Continuous)).pieces()[0].speed.peak_mm_per_s,
                     100.0);
    const Trajectory diag = plan(gcode("G0 X200 Y200\n", fast), config(BlendMode::Continuous));
    EXPECT_NEAR(diag.pieces()[0].speed.peak_mm_per_s, 100.0 * std::sqrt(2.0), 1e-12);
}

TEST(PlannerTrapezoid, EmptyAndTinyMoves) {
    const Trajectory none = plan(Program{}, config(BlendMode::Continuous));
    EXPECT_EQ(none.duration_s(), 0.0);
    EXPECT_EQ(none.at(1.0).move, -1);
    // A 1e-10 mm move is skipped: empty window at the join, no piece.
    Program p = gcode("G1 X10 F600\nG1 X20\n");
    ProgrammedMove tiny = p.moves[0];
    tiny.path = geom::Segment::line({10, 0}, {10 + 1e-10, 0});
    p.moves.insert(p.moves.begin() + 1, tiny);
    const Trajectory t = plan(p, config(BlendMode::Continuous));
    ASSERT_EQ(t.pieces().size(), 2u);
    EXPECT_EQ(t.pieces()[1].move, 2);
    const auto& w = t.move_windows();
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[1].first, w[1].second);
    EXPECT_EQ(w[1].first, w[2].first);
    EXPECT_NEAR(t.at(w[0].second).path_speed_mm_per_s, 10.0, 1e-12);  // colinear: crossed at F
}

}  // namespace
}  // namespace cnc::host::planner
