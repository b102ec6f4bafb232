// G61: every programmed move from rest to rest.
#include <cmath>

#include "planner_test_util.hpp"

namespace cnc::host::planner {
namespace {

using test::config;
using test::gcode;

TEST(PlannerExactStop, SquareIsFourTrapezoids) {
    // 20 mm sides at 100 mm/s, a = 1000: 0.1 s up (5 mm), 0.1 s cruise (10 mm), 0.1 s down: 0.3 s per side.
    const Trajectory t = plan(gcode("G1 X20 F6000\nG1 Y20\nG1 X0\nG1 Y0\n"), config(BlendMode::ExactStop));
    ASSERT_EQ(t.pieces().size(), 4u);
    for (int i = 0; i < 4; ++i) {
        const PlannedPiece& p = t.pieces()[i];
        EXPECT_EQ(p.move, i);
        EXPECT_EQ(p.speed.entry_mm_per_s, 0.0);
        EXPECT_EQ(p.speed.exit_mm_per_s, 0.0);
        EXPECT_DOUBLE_EQ(p.speed.peak_mm_per_s, 100.0);
        EXPECT_NEAR(p.speed.rise_s, 0.1, 1e-15);
        EXPECT_NEAR(p.speed.cruise_s, 0.1, 1e-14);
        EXPECT_NEAR(p.speed.fall_s, 0.1, 1e-15);
    }
    EXPECT_NEAR(t.duration_s(), 1.2, 1e-13);
    const auto& w = t.move_windows();
    ASSERT_EQ(w.size(), 4u);
    for (int i = 0; i < 4; ++i) {
        if (i > 0) {
            EXPECT_EQ(w[i].first, w[i - 1].second);
        }
        for (double tb : {w[i].first, w[i].second}) {
            const Sample s = t.at(tb);
            EXPECT_EQ(s.path_speed_mm_per_s, 0.0) << "move " << i << " t " << tb;
            EXPECT_EQ(s.vel_mm_per_s.x_mm, 0.0);
            EXPECT_EQ(s.vel_mm_per_s.y_mm, 0.0);
        }
    }
    EXPECT_NEAR(t.at(w[1].first).pos_mm.x_mm, 20.0, 1e-12);
    EXPECT_NEAR(t.at(w[1].first).pos_mm.y_mm, 0.0, 1e-12);
}

TEST(PlannerExactStop, StopsEvenBetweenColinearAndTangentMoves) {
    const Program p = gcode("G1 X10 F3000\nG1 X20\nG3 X20 Y20 I0 J10\n");
    const Trajectory t = plan(p, config(BlendMode::ExactStop));
    ASSERT_EQ(t.pieces().size(), 3u);
    for (const auto& w : t.move_windows()) {
        EXPECT_EQ(t.at(w.first).path_speed_mm_per_s, 0.0);
        EXPECT_EQ(t.at(w.second).path_speed_mm_per_s, 0.0);
    }
    // Each line alone: 10 mm at 50 mm/s: 0.05 s up and down (1.25 mm each), 7.5 mm cruise.
    EXPECT_NEAR(t.move_windows()[0].second, 0.25, 1e-14);
}

TEST(PlannerExactStop, JerkLimitedAlsoStops) {
    const Trajectory t = plan(gcode("G1 X10 F3000\nG1 Y10\n"), config(BlendMode::ExactStop, Profile::JerkLimited));
    const double tb = t.move_windows()[1].first;
    EXPECT_EQ(t.at(tb).path_speed_mm_per_s, 0.0);
    EXPECT_EQ(t.at(tb).acc_mm_per_s2.x_mm, 0.0);
    EXPECT_GT(tb, 0.0);
}

}  // namespace
}  // namespace cnc::host::planner
