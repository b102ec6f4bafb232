// step_gen core: DIR_WAIT period arithmetic and the cycle schedule of busy/DIR/STEP edges.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "fpga/core/step_schedule.hpp"

namespace cnc::fpga {
namespace {

struct E {
    std::int64_t cycle;
    StepPin pin;
    bool level;
    bool operator==(const E& o) const { return cycle == o.cycle && pin == o.pin && level == o.level; }
};

std::vector<E> all_edges(StepSchedule s) {
    std::vector<E> out;
    PinEdge e;
    while (s.next(e)) out.push_back({e.cycle, e.pin, e.level});
    return out;
}

std::ostream& operator<<(std::ostream& os, const E& e) {
    return os << "{" << e.cycle << ", pin " << static_cast<int>(e.pin) << ", " << e.level << "}";
}

TEST(StepPeriods, DominantAxisGetsNumOverFeedAndSubordinateIsStretched) {
    const FpgaConfig cfg;
    const StepPeriods p = compute_periods(320, 160, 1200, 18'750'000, 18'750'000, cfg);
    EXPECT_EQ(p.x_cycles, 15'625U);
    EXPECT_EQ(p.y_cycles, 31'250U);
    EXPECT_FALSE(p.overflow);
    // Y dominant uses num_y for both axes.
    const StepPeriods q = compute_periods(100, 300, 1000, 1'000'000, 600'000, cfg);
    EXPECT_EQ(q.y_cycles, 600U);
    EXPECT_EQ(q.x_cycles, 1'800U);
    // A tie is X dominant (abs_x >= abs_y): num_x is used.
    const StepPeriods t = compute_periods(7, 7, 1000, 700'000, 300'000, cfg);
    EXPECT_EQ(t.x_cycles, 700U);
    EXPECT_EQ(t.y_cycles, 700U);
}

TEST(StepSchedule, RunDurationIsTheMoveAtItsFeed) {
    const FpgaConfig cfg;
    // 2 mm of X at 160 steps/mm and F1200 (20 mm/s), Y half as far: 0.1 s.
    EXPECT_EQ(run_duration_ps({320, -160, 1200, 18'750'000, 18'750'000}, cfg), 100 * kPsPerMs);
    // 100 mm at F500 (8.33 mm/s) is a 12 s move, longer than the 10 s ACK timeout of seed 000 App. A.2.
    EXPECT_EQ(run_duration_ps({16'000, 0, 500, 18'750'000, 18'750'000}, cfg), 12 * kPsPerSec);
    EXPECT_EQ(run_duration_ps({0, 0, 500, 18'750'000, 18'750'000}, cfg), 0);
}

TEST(StepPeriods, FeedZeroZeroLengthSingleAxisAndFeedAboveNumerator) {
    const FpgaConfig cfg;
    EXPECT_EQ(compute_periods(5, 1, 0, 18'750'000, 18'750'000, cfg).x_cycles, 62'500U);
    EXPECT_EQ(compute_periods(5, 1, 0, 18'750'000, 18'750'000, cfg).y_cycles, 62'500U);
    EXPECT_EQ(compute_periods(0, 0, 0, 18'750'000, 18'750'000, cfg).x_cycles, 62'500U);  // feed test comes first
    EXPECT_EQ(compute_periods(0, 0, 500, 18'750'000, 18'750'000, cfg).x_cycles, 0U);
    const StepPeriods y_only = compute_periods(0, 9, 1000, 200'000, 200'000, cfg);
    EXPECT_EQ(y_only.x_cycles, 0U);
    EXPECT_EQ(y_only.y_cycles, 200U);
    const StepPeriods slow = compute_periods(5, 0, 2000, 1000, 1000, cfg);  // num/feed truncates to 0
    EXPECT_EQ(slow.x_cycles, 0U);
}

TEST(StepPeriods, OverflowWrapsLikeTheAppendixOrSaturatesInExactMode) {
    FpgaConfig exact;
    FpgaConfig wrap;
    wrap.period_arithmetic = PeriodArithmetic::Wrap32;
    // 187,500 * 73,600 = 13,800,000,000 = 3 * 2^32 + 915,098,112
    const StepPeriods e = compute_periods(73'600, 36'800, 100, 18'750'000, 18'750'000, exact);
    const StepPeriods w = compute_periods(73'600, 36'800, 100, 18'750'000, 18'750'000, wrap);
    EXPECT_TRUE(e.overflow);
    EXPECT_TRUE(w.overflow);
    EXPECT_EQ(e.x_cycles, 187'500U);
    EXPECT_EQ(w.x_cycles, 187'500U);
    EXPECT_EQ(e.y_cycles, 375'000U);
    EXPECT_EQ(w.y_cycles, 24'866U);  // 915,098,112 / 36,800
    // One subordinate step: the exact period (1.38e10 cycles) does not fit 32 bits.
    EXPECT_EQ(compute_periods(73'600, 1, 100, 18'750'000, 18'750'000, exact).y_cycles,
              std::numeric_limits<std::uint32_t>::max());
    EXPECT_EQ(compute_periods(73'600, 1, 100, 18'750'000, 18'750'000, wrap).y_cycles, 915'098'112U);
    // No subordinate axis: no product, no overflow flag.
    EXPECT_FALSE(compute_periods(73'600, 0, 100, 18'750'000, 18'750'000, exact).overflow);
}

TEST(StepPeriods, AbsAndDirFollowTheSignBit) {
    EXPECT_EQ(abs_steps(-160), 160U);
    EXPECT_EQ(abs_steps(std::numeric_limits<std::int32_t>::min()), 0x8000'0000U);
    EXPECT_TRUE(dir_level(0));
    EXPECT_TRUE(dir_level(5));
    EXPECT_FALSE(dir_level(-1));
}

TEST(StepSchedule, TwoAxisMoveEdgesFromTheListing) {
    // X 3 steps at 300 cycles, Y -1 step at 900 cycles: N = 900.
    const StepSchedule s({3, -1, 100, 30'000, 30'000}, false, false, FpgaConfig{});
    EXPECT_EQ(s.run_start(), 203);
    EXPECT_EQ(s.run_cycles(), 900);
    EXPECT_EQ(s.busy_fall(), 1103);
    EXPECT_EQ(s.idle_from(), 1104);
    const std::vector<E> expected{
        {1, StepPin::Busy, true},     {2, StepPin::DirX, true},     {203, StepPin::StepX, true},
        {203, StepPin::StepY, true},  {303, StepPin::StepX, false}, {303, StepPin::StepY, false},
        {503, StepPin::StepX, true},  {603, StepPin::StepX, false}, {803, StepPin::StepX, true},
        {903, StepPin::StepX, false}, {1103, StepPin::Busy, false}};
    EXPECT_EQ(all_edges(s), expected);
}

TEST(StepSchedule, DirEdgesOnlyWhenTheLevelChanges) {
    const StepSchedule s({-2, 0, 1000, 300'000, 300'000}, true, true, FpgaConfig{});
    const std::vector<E> edges = all_edges(s);
    ASSERT_GE(edges.size(), 2U);
    EXPECT_EQ(edges[1], (E{2, StepPin::DirX, false}));  // dir_y stays 1: zero steps count as positive
    EXPECT_EQ(edges[2].pin, StepPin::StepX);
}

TEST(StepSchedule, ShortPeriodKeepsStepHighUntilTheAxisIsDone) {
    // X 4 steps at 50 cycles (<= PULSE_HIGH), Y 3 at 66: both one long pulse; exit edge 199.
    const StepSchedule s({4, 3, 20, 1000, 1000}, true, true, FpgaConfig{});
    EXPECT_EQ(s.periods().x_cycles, 50U);
    EXPECT_EQ(s.periods().y_cycles, 66U);
    const std::vector<E> expected{{1, StepPin::Busy, true},           {203, StepPin::StepX, true},
                                  {203, StepPin::StepY, true},        {203 + 198, StepPin::StepY, false},
                                  {203 + 199, StepPin::StepX, false}, {203 + 200, StepPin::Busy, false}};
    EXPECT_EQ(all_edges(s), expected);
}

TEST(StepSchedule, PeriodOfOneWithOneStepNeverRaisesStep) {
    // The exit edge is RUN edge 0, whose step <= 0 overrides the rise.
    const StepSchedule s({1, 0, 1000, 1000, 1000}, true, true, FpgaConfig{});
    const std::vector<E> expected{{1, StepPin::Busy, true}, {204, StepPin::Busy, false}};
    EXPECT_EQ(all_edges(s), expected);
}

TEST(StepSchedule, PeriodZeroNeverStepsAndRunsOneCycle) {
    const StepSchedule s({5, 0, 2000, 1000, 1000}, true, true, FpgaConfig{});
    EXPECT_TRUE(s.has_run());
    EXPECT_EQ(s.run_cycles(), 1);
    const std::vector<E> expected{{1, StepPin::Busy, true}, {204, StepPin::Busy, false}};
    EXPECT_EQ(all_edges(s), expected);
}

TEST(StepSchedule, ZeroLengthMoveGoesFromDirWaitToDone) {
    const StepSchedule s({0, 0, 500, 18'750'000, 18'750'000}, false, false, FpgaConfig{});
    EXPECT_FALSE(s.has_run());
    EXPECT_EQ(s.busy_fall(), 203);
    EXPECT_EQ(s.idle_from(), 204);
    const std::vector<E> expected{
        {1, StepPin::Busy, true}, {2, StepPin::DirX, true}, {2, StepPin::DirY, true}, {203, StepPin::Busy, false}};
    EXPECT_EQ(all_edges(s), expected);
}

TEST(StepSchedule, PeriodOneAboveThePulseLeavesOneLowCycle) {
    const StepSchedule s({2, 0, 1000, 101'000, 101'000}, true, true, FpgaConfig{});
    const std::vector<E> expected{{1, StepPin::Busy, true},     {203, StepPin::StepX, true},
                                  {303, StepPin::StepX, false}, {304, StepPin::StepX, true},
                                  {404, StepPin::StepX, false}, {405, StepPin::Busy, false}};
    EXPECT_EQ(all_edges(s), expected);
}

TEST(StepSchedule, DirSettleMovesTheRunStart) {
    FpgaConfig cfg;
    cfg.dir_settle_cycles = 1;
    const StepSchedule s({1, 0, 1000, 300'000, 300'000}, true, true, cfg);
    EXPECT_EQ(s.run_start(), 4);
    EXPECT_EQ(s.busy_fall(), 4 + 300);
}

}  // namespace
}  // namespace cnc::fpga
