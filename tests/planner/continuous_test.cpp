// G64 P: no dead time at colinear joins, corners rounded within the tolerance, reversals stop, arcs followed.
#include <cmath>
#include <string>

#include "planner_test_util.hpp"

namespace cnc::host::planner {
namespace {

using geom::Vec2;
using test::config;
using test::contour_error;
using test::for_each_sample;
using test::gcode;

TEST(PlannerContinuous, ColinearMovesHaveNoDip) {
    // Two 50 mm halves of one 100 mm line, crossed at F: up at 1000 mm/s^2 to 100 mm/s in 0.1 s (5 mm); the
    // program's last move brakes at half that (LinuxCNC), 0.2 s over 10 mm; 85 mm of cruise, 0.85 s: 1.15 s. The
    // single 100 mm move, the program's last, has 500 mm/s^2 both ways: 0.2 + 0.8 + 0.2 s.
    const Trajectory t = plan(gcode("G1 X50 F6000\nG1 X100\n"), config(BlendMode::Continuous));
    const Trajectory merged = plan(gcode("G1 X100 F6000\n"), config(BlendMode::Continuous));
    ASSERT_EQ(t.pieces().size(), 2u);
    EXPECT_EQ(t.pieces()[0].speed.exit_mm_per_s, 100.0);
    EXPECT_NEAR(t.duration_s(), 1.15, 1e-14);
    EXPECT_NEAR(merged.duration_s(), 1.2, 1e-14);
    const double boundary = t.move_windows()[0].second;
    EXPECT_EQ(boundary, t.move_windows()[1].first);
    EXPECT_EQ(t.at(boundary).path_speed_mm_per_s, 100.0);
    double slowest = 1e9;
    for_each_sample(t, 1e-4, [&](const Sample& s) {
        if (s.t_s > 0.1 + 1e-9 && s.t_s < 0.95 - 1e-9) slowest = std::min(slowest, s.path_speed_mm_per_s);
    });
    EXPECT_NEAR(slowest, 100.0, 1e-9);
}

// LinuxCNC (tc.c tcGetOverallMaxAccel): a move whose end condition is still a parabolic blend, in G64 with nothing
// queued after it, has half the acceleration: the program's last move and the last before a dwell; not in G61/G61.1,
// and not a move that stops for a reason of its own (a change between G0 and a feed move).
TEST(PlannerContinuous, LastMoveAtHalfTheAcceleration) {
    const auto accel = [](const std::string& text, std::size_t piece) {
        return plan(gcode(text), config(BlendMode::Continuous)).pieces().at(piece).speed.limits.accel_mm_per_s2;
    };
    EXPECT_DOUBLE_EQ(accel("G1 X10 F6000\n", 0), 500.0);
    EXPECT_DOUBLE_EQ(accel("G61\nG1 X10 F6000\n", 0), 1000.0);
    EXPECT_DOUBLE_EQ(accel("G61.1\nG1 X10 F6000\n", 0), 1000.0);
    EXPECT_DOUBLE_EQ(accel("G1 X10 F6000\nG4 P1\nG1 X20\n", 0), 500.0);
    EXPECT_DOUBLE_EQ(accel("G1 X10 F6000\nG0 X20\n", 0), 1000.0);
    EXPECT_DOUBLE_EQ(accel("G1 X10 F6000\nG0 X20\n", 1), 500.0);
    // An arc: half of its tangential half, 250 mm/s^2.
    EXPECT_DOUBLE_EQ(accel("G0 X10\nG2 X10 Y0 I-10 F3000\n", 1), 250.0);
}

TEST(PlannerContinuous, ColinearMovesWithDifferentFeedsJoinAtTheLowerOne) {
    const Trajectory t = plan(gcode("G1 X50 F6000\nG1 X100 F1200\n"), config(BlendMode::Continuous));
    EXPECT_DOUBLE_EQ(t.pieces()[0].speed.exit_mm_per_s, 20.0);
    EXPECT_DOUBLE_EQ(t.pieces()[1].speed.peak_mm_per_s, 20.0);
}

TEST(PlannerContinuous, RightAngleCornerWithinTolerance) {
    const Program p = gcode("G1 X20 F3000\nG1 Y20\n");
    const Trajectory t = plan(p, config(BlendMode::Continuous));
    ASSERT_EQ(t.pieces().size(), 3u);
    const PlannedPiece& blend = t.pieces()[1];
    EXPECT_EQ(blend.move, -1);
    // R = tol cos45 / (1 - cos45), followed at sqrt((sqrt(3)/2) a R) = 10.22 mm/s (below F = 50 mm/s).
    const double r = 0.05 * std::cos(M_PI / 4) / (1 - std::cos(M_PI / 4));
    EXPECT_NEAR(blend.speed.peak_mm_per_s, std::sqrt(std::sqrt(3.0) / 2 * 1000.0 * r), 1e-9);
    EXPECT_EQ(blend.speed.entry_mm_per_s, blend.speed.peak_mm_per_s);  // no stop at the corner
    double max_err = 0.0;
    double nearest_corner = 1e9;
    double off_path_in_moves = 0.0;
    for_each_sample(t, 1e-5, [&](const Sample& s) {
        const double err = contour_error(p, s.pos_mm);
        max_err = std::max(max_err, err);
        nearest_corner = std::min(nearest_corner, geom::distance(s.pos_mm, {20, 0}));
        if (s.move >= 0) off_path_in_moves = std::max(off_path_in_moves, err);
        EXPECT_GT(s.path_speed_mm_per_s + (s.t_s <= 0.0 || s.t_s >= t.duration_s() ? 1.0 : 0.0), 0.0);
    });
    EXPECT_LE(max_err, 0.05 + 1e-9);
    EXPECT_GT(max_err, 0.0);
    // The farthest point from the two lines is the arc midpoint, R (1 - cos45) = tol cos45 from them (a kink:
    // samples 1e-4 mm apart find it within R sin45 * 1e-4 mm / R / 2).
    EXPECT_NEAR(max_err, 0.05 * std::cos(M_PI / 4), 5e-5);
    EXPECT_NEAR(nearest_corner, 0.05, 1e-7);
    EXPECT_LE(off_path_in_moves, 1e-12);
}

TEST(PlannerContinuous, ReversalStops) {
    const Trajectory t = plan(gcode("G1 X20 F3000\nG1 X0\n"), config(BlendMode::Continuous));
    ASSERT_EQ(t.pieces().size(), 2u);
    EXPECT_EQ(t.at(t.move_windows()[1].first).path_speed_mm_per_s, 0.0);
    EXPECT_NEAR(t.at(t.move_windows()[1].first).pos_mm.x_mm, 20.0, 1e-12);
}

TEST(PlannerContinuous, ZeroToleranceStopsAtCorners) {
    PlannerConfig cfg = config(BlendMode::Continuous);
    cfg.path_tolerance_mm = 0.0;
    const Trajectory t = plan(gcode("G1 X20 F3000\nG1 Y20\nG1 Y40\n"), cfg);
    ASSERT_EQ(t.pieces().size(), 3u);
    EXPECT_EQ(t.pieces()[0].speed.exit_mm_per_s, 0.0);
    EXPECT_EQ(t.pieces()[1].speed.exit_mm_per_s, 50.0);  // the colinear join is still crossed at F
}

TEST(PlannerContinuous, TangentArcFollowedOnTheCircle) {
    // Line +x into a CCW half circle about (10,10), R = 10, into a line -x: every join is tangent. With 200 mm/s
    // axes the arc is capped by the centripetal rule: sqrt((sqrt(3)/2) 1000 * 10) = 93.06 mm/s.
    PlannerConfig cfg = config(BlendMode::Continuous);
    cfg.x.max_velocity_mm_per_s = cfg.y.max_velocity_mm_per_s = 200.0;
    const Trajectory t = plan(gcode("G1 X10 F12000\nG3 X10 Y20 I0 J10\nG1 X-30\n"), cfg);
    ASSERT_EQ(t.pieces().size(), 3u);
    const double v_cap = std::sqrt(std::sqrt(3.0) / 2 * 1000.0 * 10.0);
    EXPECT_NEAR(t.pieces()[1].speed.limits.velocity_mm_per_s, v_cap, 1e-9);
    EXPECT_NEAR(t.pieces()[1].speed.peak_mm_per_s, v_cap, 1e-9);
    EXPECT_NEAR(t.pieces()[1].speed.limits.accel_mm_per_s2, 500.0, 1e-12);
    int on_arc = 0;
    double max_centripetal = 0.0;
    for_each_sample(t, 1e-4, [&](const Sample& s) {
        if (s.move != 1) return;
        ++on_arc;
        const Vec2 c{10, 10};
        EXPECT_NEAR(geom::distance(s.pos_mm, c), 10.0, 1e-9);
        const Vec2 inward = unit(c - s.pos_mm);
        const double centripetal = geom::dot(s.acc_mm_per_s2, inward);
        EXPECT_NEAR(centripetal, s.path_speed_mm_per_s * s.path_speed_mm_per_s / 10.0, 1e-6);
        max_centripetal = std::max(max_centripetal, centripetal);
        EXPECT_LE(geom::norm(s.acc_mm_per_s2), 1000.0 + 1e-6);
    });
    EXPECT_GT(on_arc, 3000);
    EXPECT_LE(max_centripetal, std::sqrt(3.0) / 2 * 1000.0 + 1e-6);
    EXPECT_NEAR(max_centripetal, std::sqrt(3.0) / 2 * 1000.0, 1e-6);
}

TEST(PlannerContinuous, ArcWithOffCircleEndJoinsWithoutAStep) {
    // The end (20.008, 10) lies 0.008 mm outside the start circle about (10,10) (the interpreter allows 0.01):
    // the planner's spiral still leaves along the line's direction and joins the next line along its own
    // direction, at the same speed, so neither join is a corner and the velocity never jumps.
    const Program p = gcode("G1 X10 F3000\nG3 X20.008 Y10 I0 J10\nG1 Y30\n");
    const Trajectory t = plan(p, config(BlendMode::Continuous));
    ASSERT_EQ(t.pieces().size(), 3u);
    EXPECT_EQ(t.pieces()[0].speed.exit_mm_per_s, 50.0);
    EXPECT_EQ(t.pieces()[1].speed.exit_mm_per_s, 50.0);
    const double dt = 1e-5;
    Sample prev = t.at(0.0);
    double worst_dv = 0.0;
    for_each_sample(t, dt, [&](const Sample& s) {
        worst_dv = std::max(worst_dv, geom::norm(s.vel_mm_per_s - prev.vel_mm_per_s));
        prev = s;
    });
    EXPECT_LE(worst_dv, 1000.0 * dt * (1.0 + 1e-6));
    EXPECT_EQ(t.at(t.move_windows()[1].second).pos_mm.x_mm, 20.008);
}

TEST(PlannerContinuous, LineIntoArcCornerIsBlended) {
    // +x line into a clockwise half circle starting upwards and ending downwards, then +x again: two 90 degree
    // corners between a line and an arc.
    const Program p = gcode("G1 X10 F3000\nG2 X20 Y0 I5 J0\nG1 X30\n");
    const Trajectory t = plan(p, config(BlendMode::Continuous));
    ASSERT_EQ(t.pieces().size(), 5u);
    EXPECT_EQ(t.pieces()[1].move, -1);
    EXPECT_EQ(t.pieces()[3].move, -1);
    double max_err = 0.0;
    for_each_sample(t, 1e-5, [&](const Sample& s) {
        max_err = std::max(max_err, contour_error(p, s.pos_mm));
        if (s.move == 1) {
            EXPECT_NEAR(geom::distance(s.pos_mm, {15, 0}), 5.0, 1e-9);
        }
        if (s.move >= 0) {
            EXPECT_LE(contour_error(p, s.pos_mm), 1e-9);
        }
        EXPECT_GT(s.path_speed_mm_per_s + (s.t_s <= 0.0 || s.t_s >= t.duration_s() ? 1.0 : 0.0), 0.0);
    });
    EXPECT_LE(max_err, 0.05 + 1e-9);
    EXPECT_GT(max_err, 0.02);
}

TEST(PlannerContinuous, LookaheadOfOneMoveStopsEverywhere) {
    // Ten colinear 1 mm moves at 100 mm/s. One move of look-ahead: ten triangles of 2 sqrt(1 mm / a) each.
    // Enough look-ahead: one 10 mm move, 5 mm up to exactly 100 mm/s and 5 mm down: 0.2 s.
    std::string text = "G1 X1 F6000\n";
    for (int i = 2; i <= 10; ++i) text += "G1 X" + std::to_string(i) + "\n";
    const Program p = gcode(text);
    // Exact path (G61): the colinear joins crossed, the last move at the whole acceleration.
    PlannerConfig cfg = config(BlendMode::ExactPath);
    cfg.lookahead_moves = 1;
    EXPECT_NEAR(plan(p, cfg).duration_s(), 10 * 2 * std::sqrt(0.001), 1e-12);
    cfg.lookahead_moves = 10;
    EXPECT_NEAR(plan(p, cfg).duration_s(), 0.2, 1e-12);
    // Three moves: in the middle of move k the machine must stop within the 2.5 mm left of moves k..k+2:
    // sqrt(2 a 2.5 mm) = 70.71 mm/s at most.
    cfg.lookahead_moves = 3;
    const Trajectory t3 = plan(p, cfg);
    double fastest = 0.0;
    for (const PlannedPiece& piece : t3.pieces()) fastest = std::max(fastest, piece.speed.peak_mm_per_s);
    EXPECT_NEAR(fastest, std::sqrt(5000.0), 1e-9);
}

TEST(PlannerContinuous, JerkLimitedColinearMovesKeepTheirSpeed) {
    const Trajectory t = plan(gcode("G1 X50 F6000\nG1 X100\n"), config(BlendMode::Continuous, Profile::JerkLimited));
    EXPECT_EQ(t.pieces()[0].speed.exit_mm_per_s, 100.0);
    const double boundary = t.move_windows()[0].second;
    for (double dt : {-0.05, -1e-3, 0.0, 1e-3, 0.05}) {
        EXPECT_EQ(t.at(boundary + dt).path_speed_mm_per_s, 100.0) << dt;
    }
}

}  // namespace
}  // namespace cnc::host::planner
