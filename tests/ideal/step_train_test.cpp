// The ideal controller's STEP/DIR edges from its step instants (sim/architectures/ideal/step_train.hpp), against the
// DRV8825's timing rules (data sheet SLVSA73F §7.6): tWH(STEP) >= 1.9 us, tSU(DIR) >= 650 ns.
#include <gtest/gtest.h>

#include <vector>

#include "architectures/ideal/step_train.hpp"

namespace cnc::sim::ideal {
namespace {

constexpr TimePs kUs = kPsPerUs;

std::vector<PinEdge> all(StepTrain& t) {
    return t.take();
}

TEST(StepTrain, EachStepRisesAtItsInstantAndStaysHighTwoMicroseconds) {
    StepTrain t;
    t.add(100 * kUs, 1);
    t.add(400 * kUs, 1);
    t.finish();
    const std::vector<PinEdge> e = all(t);
    ASSERT_EQ(e.size(), 5u);
    // DIR goes high (the positive way) 1 us before the first rise: past the 650 ns setup.
    EXPECT_EQ(e[0].t_ps, 99 * kUs);
    EXPECT_FALSE(e[0].step);
    EXPECT_TRUE(e[0].level);
    EXPECT_EQ(e[1].t_ps, 100 * kUs);
    EXPECT_TRUE(e[1].step && e[1].level);
    EXPECT_EQ(e[2].t_ps, 102 * kUs);  // 2 us high: past the 1.9 us tWH
    EXPECT_TRUE(e[2].step && !e[2].level);
    EXPECT_EQ(e[3].t_ps, 400 * kUs);
    EXPECT_EQ(e[4].t_ps, 402 * kUs);
    EXPECT_GE(kStepHighPs, 1'900'000);
    EXPECT_GE(kDirLeadPs, 650'000);
}

TEST(StepTrain, AReversalTurnsDirOneMicrosecondBeforeTheRiseOfTheNewDirection) {
    StepTrain t;
    t.add(10 * kUs, 1);
    t.add(50 * kUs, -1);
    t.finish();
    const std::vector<PinEdge> e = all(t);
    ASSERT_EQ(e.size(), 6u);
    EXPECT_EQ(e[3].t_ps, 49 * kUs);
    EXPECT_FALSE(e[3].step);
    EXPECT_FALSE(e[3].level);  // DIR low: the negative way
    EXPECT_EQ(e[4].t_ps, 50 * kUs);
}

TEST(StepTrain, RisesCloserThanTheDriverAllowsShareTheTimeHalfway) {
    // 1.2 us apart, reversing: the fall and the DIR change go halfway, and the rises keep their instants.
    StepTrain t;
    t.add(10 * kUs, 1);
    t.add(10 * kUs + 1'200'000, -1);
    t.finish();
    const std::vector<PinEdge> e = all(t);
    ASSERT_EQ(e.size(), 6u);
    EXPECT_EQ(e[2].t_ps, 10 * kUs + 600'000);  // the first fall, halfway
    EXPECT_TRUE(e[2].step);
    EXPECT_EQ(e[3].t_ps, 10 * kUs + 600'000);  // DIR, halfway too
    EXPECT_FALSE(e[3].step);
    EXPECT_EQ(e[4].t_ps, 10 * kUs + 1'200'000);
}

TEST(StepTrain, APendingFallIsMadeOnceNoStepCanComeBeforeIt) {
    StepTrain t;
    t.add(10 * kUs, 1);
    (void)t.take();
    EXPECT_EQ(t.final_until_ps(), 10 * kUs + 1);  // the fall waits for the next rise, which may come sooner
    t.advance(13 * kUs);
    EXPECT_TRUE(t.take().empty());
    t.advance(14 * kUs);  // a rise from 14 us on leaves the fall its whole 2 us
    const std::vector<PinEdge> e = t.take();
    ASSERT_EQ(e.size(), 1u);
    EXPECT_EQ(e[0].t_ps, 12 * kUs);
    EXPECT_EQ(t.final_until_ps(), 13 * kUs);  // the next DIR edge is at most 1 us before its rise
}

}  // namespace
}  // namespace cnc::sim::ideal
