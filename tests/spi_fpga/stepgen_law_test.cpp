// The hm2 stepgen law (models/host/servo/core/stepgen_law.hpp) and the rate words (rate_word.hpp), in steps.
#include <gtest/gtest.h>

#include "host/servo/core/rate_word.hpp"
#include "host/servo/core/stepgen_law.hpp"

using namespace cnc::host::servo;

namespace {
constexpr double kT = 1e-3;  // 1 ms servo period
// 1000 mm/s^2 x 1.25 margin x 160 steps/mm = 200,000 steps/s^2: 200 steps/s per period
const StepgenParams kParams{20'000.0, 200'000.0, 0.5, 1.0};
}  // namespace

TEST(StepgenLaw, CruiseOnePeriodBehindHoldsTheFeedForward) {
    // The axis is one period (3.2 steps at 3200 steps/s) behind its command: err_at_match 0, vel = ff_vel.
    StepgenState s{1000.0 - 3.2, 3200.0};
    const StepgenOutput out = stepgen_velocity(kParams, s, 1000.0, 1000.0 - 3.2, kT);
    EXPECT_NEAR(out.err_at_match_steps, 0.0, 1e-9);
    EXPECT_TRUE(out.in_deadband);
    EXPECT_DOUBLE_EQ(out.velocity_steps_per_s, (1000.0 - (1000.0 - 3.2)) / kT);
    EXPECT_DOUBLE_EQ(s.old_pos_cmd_steps, 1000.0);
}

TEST(StepgenLaw, ErrorPastTheDeadbandIsHalfCorrectedWithinTheAccelLimit) {
    // 0.6 steps behind the one-period lag: -0.5 * (-0.6) / T = +300 steps/s, clipped to vel_fb + A T = +200.
    StepgenState s{1000.0 - 3.2, 3200.0};
    StepgenParams tight = kParams;
    tight.deadband_steps = 0.5;
    const StepgenOutput out = stepgen_velocity(tight, s, 1000.0, 1000.0 - 3.2 - 0.6, kT);
    EXPECT_NEAR(out.err_at_match_steps, -0.6, 1e-9);
    EXPECT_FALSE(out.in_deadband);
    EXPECT_NEAR(out.velocity_steps_per_s, 3400.0, 1e-9);
    // 0.3 steps past a wider deadband: nothing but the feed-forward
    StepgenState s2{1000.0 - 3.2, 3200.0};
    EXPECT_NEAR(stepgen_velocity(kParams, s2, 1000.0, 1000.0 - 3.2 - 0.3, kT).velocity_steps_per_s, 3200.0, 1e-9);
}

// The position gain where the acceleration limit does not clip it. The axis cruises at its command's 3200 steps/s
// (vel_fb = ff_vel: t_match = 0) and lags 0.6 steps more than the one-period lag. By hand, from the hm2 formula:
//   ff_vel       = (1000 - 996.8) / 1 ms = 3200 steps/s
//   pos_at_match = pos_fb + (3200 + 3200) / 2 x (0 + 1 ms) = 996.2 + 3.2 = 999.4
//   err_at_match = 999.4 - (1000 + 3200 x 0) = -0.6 steps, past the 0.5-step deadband
//   vel          = ff_vel - gain x err / T = 3200 + gain x 600 steps/s
// with A = 10^6 steps/s^2 the velocity may change by A T = 1000 steps/s, more than the correction. hm2's gain 0.5
// gives 3500 steps/s: over the next period the axis moves 3.5 steps, half the 0.6-step error closed; gain 1 gives
// 3800 steps/s and closes it all (996.2 + 3.8 = 1000, the command).
TEST(StepgenLaw, PositionGainCorrectsThatShareOfTheErrorInOnePeriod) {
    StepgenParams loose = kParams;
    loose.max_accel_steps_per_s2 = 1'000'000.0;
    loose.deadband_steps = 0.5;
    StepgenState half{1000.0 - 3.2, 3200.0};
    const StepgenOutput out = stepgen_velocity(loose, half, 1000.0, 1000.0 - 3.2 - 0.6, kT);
    EXPECT_NEAR(out.err_at_match_steps, -0.6, 1e-9);
    EXPECT_NEAR(out.velocity_steps_per_s, 3500.0, 1e-6);
    loose.position_gain = 1.0;
    StepgenState all{1000.0 - 3.2, 3200.0};
    EXPECT_NEAR(stepgen_velocity(loose, all, 1000.0, 1000.0 - 3.2 - 0.6, kT).velocity_steps_per_s, 3800.0, 1e-6);
}

TEST(StepgenLaw, StartFromRestMatchesTheFirstPeriodsVelocity) {
    // Trapezoid at 160,000 steps/s^2: after 1 ms the command is 0.08 steps ahead, ff_vel 80 steps/s.
    // t_match = 80 / 200,000 = 0.4 ms; pos_at_match = 40 x 1.4 ms = 0.056; cmd at match 0.08 + 0.032 = 0.112.
    StepgenState s{0.0, 0.0};
    const StepgenOutput out = stepgen_velocity(kParams, s, 0.08, 0.0, kT);
    EXPECT_NEAR(out.err_at_match_steps, -0.056, 1e-12);
    EXPECT_NEAR(out.velocity_steps_per_s, 80.0, 1e-9);
}

TEST(StepgenLaw, AVelocityStepBeyondOnePeriodRampsAtTheLimit) {
    // ff_vel jumps to 1000 steps/s: t_match = 5 ms > T, err_at_match = 500 x 6 ms - 1000 x 5 ms = -2 steps;
    // ramping down instead would give |-2 + 2 x (-2)| = 6 > 2, so it ramps up: 0 + 200.
    StepgenState s{-1.0, 0.0};
    const StepgenOutput out = stepgen_velocity(kParams, s, 0.0, 0.0, kT);
    EXPECT_NEAR(out.err_at_match_steps, -2.0, 1e-9);
    EXPECT_NEAR(out.velocity_steps_per_s, 200.0, 1e-9);
}

TEST(StepgenLaw, VelocityLimit) {
    StepgenState s{0.0, 19'950.0};
    // ff 30,000 steps/s: the ramp gives 20,150, clipped to 20,000
    EXPECT_DOUBLE_EQ(stepgen_velocity(kParams, s, 30.0, 0.0, kT).velocity_steps_per_s, 20'000.0);
}

TEST(RateWord, PeriodToTheNearestClockDirectionAndStop) {
    const auto w = rate_word_for(3200.0, 50'000'000, 101);  // 15,625 clocks = 312.5 us
    EXPECT_EQ(w.period_cycles, 15'625U);
    EXPECT_TRUE(w.forward);
    const auto r = rate_word_for(-1600.0, 50'000'000, 101);
    EXPECT_EQ(r.period_cycles, 31'250U);
    EXPECT_FALSE(r.forward);
    EXPECT_EQ(rate_word_for(0.0, 50'000'000, 101).period_cycles, 0U);
    EXPECT_DOUBLE_EQ(signed_rate(r, 50'000'000), -1600.0);
    EXPECT_DOUBLE_EQ(signed_rate({0, false}, 50'000'000), 0.0);
}

TEST(RateWord, RatesBeyondThe30BitPeriodAreStops) {
    // 50e6 / 0.0466 = 1,072,961,373 clocks fits 2^30 - 1; 50e6 / 0.04656 = 1,073,883,161.5 does not.
    EXPECT_EQ(rate_word_for(0.0466, 50'000'000, 101).period_cycles, 1'072'961'373U);
    EXPECT_EQ(rate_word_for(0.04656, 50'000'000, 101).period_cycles, 0U);
    EXPECT_EQ(rate_word_for(-1e-9, 50'000'000, 101).period_cycles, 0U);
}

TEST(RateWord, AHalfClockTieKeepsThePreviousWord) {
    // 800 mm/min at 160 steps/mm = 2133.33 steps/s = 23,437.5 clocks: either neighbour stays.
    const double v = 800.0 / 60.0 * 160.0;
    EXPECT_EQ(rate_word_for(v, 50'000'000, 101).period_cycles, 23'438U);  // llround: ties away from zero
    EXPECT_EQ(rate_word_for(v, 50'000'000, 101, {23'437, true}).period_cycles, 23'437U);
    EXPECT_EQ(rate_word_for(v, 50'000'000, 101, {23'438, true}).period_cycles, 23'438U);
    // a word further away, the other direction or a stop are replaced
    EXPECT_EQ(rate_word_for(v, 50'000'000, 101, {23'436, true}).period_cycles, 23'438U);
    EXPECT_TRUE(rate_word_for(v, 50'000'000, 101, {23'437, false}).forward);
    EXPECT_EQ(rate_word_for(v, 50'000'000, 101, {0, true}).period_cycles, 23'438U);
}
