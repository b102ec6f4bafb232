#include "mechanics/core/step_size_control.hpp"

#include <gtest/gtest.h>

namespace cnc::mech {
namespace {

// Goldens from the formulas of Hairer's DOPRI5 (Hairer, Norsett, Wanner, Solving ODE I, §II.4; beta = 0.04,
// exponent 0.2 - 0.75 beta = 0.17, safety 0.9, growth at most 10 x, shrink at most 5 x), computed by hand.

TEST(StepSizeControl, AcceptedStepGrowsByThePiFactor) {
    // First accepted step, err = 1e-5, last error taken as 1e-4: fac = 1e-5^0.17 / 1e-4^0.04 / 0.9 = 0.22686,
    // so the next step is 1 / 0.22686 = 4.4080 x this one.
    StepSizeControl c;
    EXPECT_NEAR(c.next_step_s(1e-5, 1e-5), 4.4080e-5, 1e-9);
}

TEST(StepSizeControl, RejectedStepShrinksAndTheNextAcceptedOneDoesNotGrow) {
    // err = 32: 32^0.17 / 0.9 = 2.0028, the retry is 0.49931 x the step. Then an accepted err = 1e-6 would grow
    // the step (1e-6^0.17 / 1e-4^0.04 / 0.9 = 0.15338 -> 6.5 x), but after a rejection it stays.
    StepSizeControl c;
    EXPECT_NEAR(c.next_step_s(1e-4, 32.0), 4.9931e-5, 1e-9);
    EXPECT_DOUBLE_EQ(c.next_step_s(5e-5, 1e-6), 5e-5);
}

TEST(StepSizeControl, GrowthAndShrinkAreBounded) {
    // An exact step grows 10 x at most; err = 1e6 would ask for 1e6^0.17 / 0.9 = 11.6 x smaller: 5 x at most.
    StepSizeControl c;
    EXPECT_DOUBLE_EQ(c.next_step_s(1e-5, 0.0), 1e-4);
    EXPECT_DOUBLE_EQ(c.next_step_s(1e-5, 1e6), 2e-6);
}

}  // namespace
}  // namespace cnc::mech
