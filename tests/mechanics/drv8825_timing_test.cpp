#include <gtest/gtest.h>

#include "mechanics/core/drv8825_timing.hpp"

using cnc::TimePs;
using namespace cnc::mech;

namespace {

constexpr TimePs kUs = cnc::kPsPerUs;

void pulse(Drv8825TimingChecker& c, TimePs t_rise, TimePs high) {
    c.on_step(t_rise, true);
    c.on_step(t_rise + high, false);
}

}  // namespace

TEST(Drv8825Timing, CleanFpgaTraceHasNoViolations) {
    // seed 000 §5.2.4: STEP high 100 clocks = 2 us; DIR -> first STEP 201 clocks = 4.02 us (derived timeline);
    // 312.5 us period (160 steps/mm at 1200 mm/min).
    Drv8825TimingChecker c;
    c.on_dir(100 * kUs, true);
    TimePs t = 100 * kUs + 4'020'000;
    for (int i = 0; i < 20; ++i, t += 312'500'000) pulse(c, t, 2 * kUs);
    const TimePs last_rise = t - 312'500'000;
    c.on_dir(last_rise + 500 * kUs, false);
    for (int i = 0; i < 5; ++i) pulse(c, last_rise + 500 * kUs + 4'020'000 + i * 312'500'000, 2 * kUs);

    const TimingStats& s = c.stats();
    EXPECT_EQ(s.total_violations(), 0);
    EXPECT_EQ(s[TimingRule::StepHigh].checks, 25);
    EXPECT_EQ(s[TimingRule::StepHigh].worst_ps, 2 * kUs);
    EXPECT_EQ(s[TimingRule::StepLow].worst_ps, 310'500'000);
    EXPECT_EQ(s[TimingRule::DirSetup].worst_ps, 4'020'000);
    EXPECT_EQ(s[TimingRule::DirHold].worst_ps, 500 * kUs);
    EXPECT_EQ(s[TimingRule::StepRate].worst_ps, 312'500'000);
}

TEST(Drv8825Timing, ShortHighPulse) {
    Drv8825TimingChecker c;
    pulse(c, 10 * kUs, 2 * kUs);
    pulse(c, 20 * kUs, 1'500'000);
    pulse(c, 30 * kUs, 1'899'999);
    EXPECT_EQ(c.stats()[TimingRule::StepHigh].violations, 2);
    EXPECT_EQ(c.stats()[TimingRule::StepHigh].worst_ps, 1'500'000);
    EXPECT_EQ(c.stats().total_violations(), 2);
}

TEST(Drv8825Timing, ShortLowTimeAndTooFastRate) {
    Drv8825TimingChecker c;
    pulse(c, 10 * kUs, 2 * kUs);
    pulse(c, 13 * kUs, 2 * kUs);  // low 1 us, period 3 us (333 kHz)
    EXPECT_EQ(c.stats()[TimingRule::StepLow].violations, 1);
    EXPECT_EQ(c.stats()[TimingRule::StepLow].worst_ps, 1 * kUs);
    EXPECT_EQ(c.stats()[TimingRule::StepRate].violations, 1);
    EXPECT_EQ(c.stats()[TimingRule::StepRate].worst_ps, 3 * kUs);
}

TEST(Drv8825Timing, RateAloneAndItsBoundary) {
    Drv8825TimingChecker c;
    pulse(c, 0, 1'900'000);
    pulse(c, 3'800'000, 1'900'000);  // legal widths, 263 kHz
    pulse(c, 7'800'000, 1'900'000);  // 4 us: exactly 250 kHz, allowed
    EXPECT_EQ(c.stats()[TimingRule::StepRate].violations, 1);
    EXPECT_EQ(c.stats()[TimingRule::StepRate].worst_ps, 3'800'000);
    EXPECT_EQ(c.stats()[TimingRule::StepRate].checks, 2);
    EXPECT_EQ(c.stats()[TimingRule::StepHigh].violations, 0);
    EXPECT_EQ(c.stats()[TimingRule::StepLow].violations, 0);
}

TEST(Drv8825Timing, DirSetupAndHold) {
    Drv8825TimingChecker c;
    c.on_dir(9'900'000, true);  // 100 ns before the rise
    pulse(c, 10 * kUs, 2 * kUs);
    c.on_step(100 * kUs, true);
    c.on_dir(100 * kUs + 300'000, false);  // 300 ns after the rise
    c.on_step(102 * kUs, false);
    EXPECT_EQ(c.stats()[TimingRule::DirSetup].violations, 1);
    EXPECT_EQ(c.stats()[TimingRule::DirSetup].worst_ps, 100'000);
    EXPECT_EQ(c.stats()[TimingRule::DirHold].violations, 1);
    EXPECT_EQ(c.stats()[TimingRule::DirHold].worst_ps, 300'000);
    EXPECT_EQ(c.stats().total_violations(), 2);
}

TEST(Drv8825Timing, SimultaneousDirChangeIsZeroSetupAndRepeatsAreNotEdges) {
    Drv8825TimingChecker c;
    c.set_initial_levels(false, true);
    c.on_dir(5 * kUs, true);    // not a change
    c.on_step(5 * kUs, false);  // not a change
    c.on_dir(10 * kUs, false);
    c.on_step(10 * kUs, true);
    EXPECT_EQ(c.stats()[TimingRule::DirSetup].violations, 1);
    EXPECT_EQ(c.stats()[TimingRule::DirSetup].worst_ps, 0);
    EXPECT_EQ(c.stats()[TimingRule::DirHold].checks, 0);
    EXPECT_EQ(c.stats()[TimingRule::StepLow].checks, 0);
}

TEST(Drv8825Timing, SameInstantDirChangeIsSetupWhicheverComesFirst) {
    Drv8825TimingChecker c;
    pulse(c, 10 * kUs, 2 * kUs);
    c.on_step(20 * kUs, true);
    c.on_dir(20 * kUs, true);  // fed after the rise of the same instant
    c.on_step(22 * kUs, false);
    EXPECT_EQ(c.stats()[TimingRule::DirSetup].violations, 1);
    EXPECT_EQ(c.stats()[TimingRule::DirSetup].worst_ps, 0);
    EXPECT_EQ(c.stats()[TimingRule::DirHold].checks, 0);
    EXPECT_EQ(c.stats().total_violations(), 1);
}
