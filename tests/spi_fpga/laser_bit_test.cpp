// The laser bit of the spi-fpga host's frames (models/host/servo/core/laser_bit.hpp) against times worked out from
// the G-code: at F600 (10 mm/s) with the default 1000 mm/s^2, a 10 mm move from rest to rest takes
// 10 / 10 + 10 / 1000 = 1.01 s (0.01 s ramps at each end).
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "host/core/gcode.hpp"
#include "host/core/planner/planner.hpp"
#include "host/servo/core/laser_bit.hpp"
#include "support/fed_job.hpp"

using namespace cnc::host;
using namespace cnc::host::servo;

namespace {

Program program(const std::string& text) {
    std::istringstream in(text);
    return interpret(in, "test.nc", InterpreterOptions{});
}

planner::PlannerConfig planner_config(planner::BlendMode mode) {
    planner::PlannerConfig pc;
    pc.mode = mode;
    return pc;
}

}  // namespace

TEST(LaserIntent, CuttingMovesUnderM3OrM4WithPowerOnly) {
    const Program p = program("G1 X1 F600\nM3 S1000\nG1 X2\nM5\nG1 X3\nM3 S0\nG1 X4\nM4 S10\nG0 X5\nG2 X7 I1\n");
    EXPECT_EQ(laser_intent(p), (std::vector<bool>{false, true, false, false, false, true}));
}

TEST(LaserBit, ExactStopFollowsEachMoveAndIsOffAtRest) {
    // Moves: 0 cut X0->10 on [0, 1.01]; 1 Y0->10 under M5 [1.01, 2.02]; 2 G0 X0; 3 Y10->0 under M3 S1000 (S stays
    // in force through M5); then a 1 s dwell after the last move.
    const std::string text = "M3 S1000\nG1 X10 F600\nM5\nG1 Y10\nM3\nG0 X0\nG1 Y0\nG4 P1\n";
    const Program p = program(text);
    const planner::Trajectory t = planner::plan(p, planner_config(planner::BlendMode::ExactStop));
    ASSERT_EQ(t.move_windows().size(), 4U);
    const double first_end = t.move_windows()[0].second;
    ASSERT_DOUBLE_EQ(first_end, 1.01);
    const double rapid_begin = t.move_windows()[2].first;
    const double last_begin = t.move_windows()[3].first;
    const double last_end = t.move_windows()[3].second;
    // The bit reads the plan as it is read (the times above are the whole plan's).
    cnc::test::FedJob fed(text, planner_config(planner::BlendMode::ExactStop));
    LaserBit bit(fed.plan, laser_intent(p));
    EXPECT_FALSE(bit.next(0.0, 0.0));  // period 0: the clock has not moved
    EXPECT_TRUE(bit.next(0.0, 0.001));
    EXPECT_TRUE(bit.next(first_end - 0.001, first_end));   // reaching the rest point: the move ending there
    EXPECT_FALSE(bit.next(first_end, first_end));          // held while the axes land
    EXPECT_FALSE(bit.next(first_end, first_end + 0.001));  // M5
    EXPECT_FALSE(bit.next(rapid_begin, rapid_begin + 0.001));
    EXPECT_TRUE(bit.next(last_begin, last_begin + 0.001));
    EXPECT_TRUE(bit.next(last_end - 0.001, last_end));
    EXPECT_FALSE(bit.next(last_end, last_end + 0.5));  // the dwell after the last move: at rest
    EXPECT_DOUBLE_EQ(t.duration_s(), last_end + 1.0);
}

TEST(LaserBit, ACornerBlendKeepsThePreviousBitOnlyIntoAMoveThatWantsTheLaser) {
    // Continuous: two 90-degree corners blended; the laser is wanted in the first two moves, M5 in the third.
    const std::string text = "M3 S1000\nG1 X10 F600\nG1 Y10\nM5\nG1 X0\n";
    const Program p = program(text);
    const planner::Trajectory t = planner::plan(p, planner_config(planner::BlendMode::Continuous));
    std::vector<const planner::PlannedPiece*> blends;
    for (const planner::PlannedPiece& piece : t.pieces()) {
        if (piece.move < 0) blends.push_back(&piece);
    }
    ASSERT_EQ(blends.size(), 2U);
    const double mid0 = (blends[0]->t_begin_s + blends[0]->t_end_s) / 2;
    const double mid1 = (blends[1]->t_begin_s + blends[1]->t_end_s) / 2;
    const double move1_mid = (t.move_windows()[1].first + t.move_windows()[1].second) / 2;
    cnc::test::FedJob fed(text, planner_config(planner::BlendMode::Continuous));
    LaserBit bit(fed.plan, laser_intent(p));
    EXPECT_TRUE(bit.next(0.0, 0.5));
    EXPECT_TRUE(bit.next(0.5, mid0));  // between two wanted moves, after an on period: on
    EXPECT_TRUE(bit.next(mid0, move1_mid));
    EXPECT_FALSE(bit.next(move1_mid, mid1));  // into the M5 move: off already in the blend
    EXPECT_FALSE(bit.next(mid1, t.move_windows()[2].first + 0.01));
    // The blend between the two wanted moves after an off period stays off: it follows the period before it.
    cnc::test::FedJob fed_again(text, planner_config(planner::BlendMode::Continuous));
    LaserBit from_off(fed_again.plan, laser_intent(p));
    EXPECT_FALSE(from_off.next(0.0, 0.0));
    EXPECT_FALSE(from_off.next(mid0, mid0 + 1e-6));
}
