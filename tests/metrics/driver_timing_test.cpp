#include <gtest/gtest.h>

#include "metrics/driver_timing.hpp"
#include "metrics_test_util.hpp"

namespace cnc::metrics {
namespace {

using test::dir_log;
using test::grid;
using test::step_log;

constexpr TimePs kUs = kPsPerUs;
constexpr TimePs kNs = kPsPerNs;

TEST(MetricsDriverTiming, CleanTwoMicrosecondPulsesAtFourMicrosecondsPass) {
    // 2 us high, 2 us low: 250 kHz exactly (the limit itself is allowed). DIR changes 1 us after a
    // step (hold 1 us) and exactly 650 ns before another (setup at the limit).
    const std::vector<TimePs> rises = grid(10 * kUs, 4 * kUs, 10);  // 10, 14, ..., 46 us
    const EdgeLog dir = dir_log({19 * kUs, 30 * kUs - 650 * kNs});
    const DriverTimingReport r = check_driver_timing(step_log(rises), dir, DriverLimits{});
    EXPECT_EQ(r.total_violations(), 0U);
    EXPECT_EQ(r[DriverRule::StepHigh].checked, 10U);
    EXPECT_EQ(*r[DriverRule::StepHigh].min_ps, 2 * kUs);
    EXPECT_EQ(r[DriverRule::StepLow].checked, 9U);
    EXPECT_EQ(*r[DriverRule::StepLow].min_ps, 2 * kUs);
    EXPECT_EQ(r[DriverRule::Rate].checked, 9U);
    EXPECT_EQ(*r[DriverRule::Rate].min_ps, 4 * kUs);
    EXPECT_EQ(r[DriverRule::DirSetup].checked, 7U);  // the rises after the first DIR change
    EXPECT_EQ(*r[DriverRule::DirSetup].min_ps, 650 * kNs);
    EXPECT_EQ(r[DriverRule::DirHold].checked, 2U);
    EXPECT_EQ(*r[DriverRule::DirHold].min_ps, 1 * kUs);
    EXPECT_FALSE(r[DriverRule::DirHold].first_violation_at_ps.has_value());
}

TEST(MetricsDriverTiming, ShortHighPulsesAreCountedWithTheShortestAsWorst) {
    EdgeLog step{"step_x", false, {}};
    step.add(0, true);
    step.add(1'800 * kNs, false);  // 1.8 us
    step.add(10 * kUs, true);
    step.add(12 * kUs, false);     // 2 us, fine
    step.add(20 * kUs, true);
    step.add(21'500 * kNs, false);  // 1.5 us
    const DriverTimingReport r = check_driver_timing(step, EdgeLog{}, DriverLimits{});
    EXPECT_EQ(r[DriverRule::StepHigh].violations, 2U);
    EXPECT_EQ(*r[DriverRule::StepHigh].min_ps, 1'500 * kNs);
    EXPECT_EQ(*r[DriverRule::StepHigh].first_violation_at_ps, 1'800 * kNs);
    EXPECT_EQ(r.total_violations(), 2U);
}

TEST(MetricsDriverTiming, ShortLowTimesAreCounted) {
    // 2.5 us high every 4 us: 1.5 us low, rate still within 250 kHz.
    const DriverTimingReport r =
        check_driver_timing(step_log(grid(0, 4 * kUs, 5), 2'500 * kNs), EdgeLog{}, DriverLimits{});
    EXPECT_EQ(r[DriverRule::StepLow].violations, 4U);
    EXPECT_EQ(*r[DriverRule::StepLow].min_ps, 1'500 * kNs);
    EXPECT_EQ(r[DriverRule::Rate].violations, 0U);
    EXPECT_EQ(r[DriverRule::StepHigh].violations, 0U);
}

TEST(MetricsDriverTiming, DirSetupViolationsIncludingASimultaneousChange) {
    const std::vector<TimePs> rises = grid(10 * kUs, 10 * kUs, 4);  // 10, 20, 30, 40 us
    // 600 ns before the 20 us step, and exactly at the 40 us step.
    const EdgeLog dir = dir_log({20 * kUs - 600 * kNs, 40 * kUs});
    const DriverTimingReport r = check_driver_timing(step_log(rises), dir, DriverLimits{});
    EXPECT_EQ(r[DriverRule::DirSetup].violations, 2U);
    EXPECT_EQ(*r[DriverRule::DirSetup].min_ps, 0);
    EXPECT_EQ(*r[DriverRule::DirSetup].first_violation_at_ps, 20 * kUs);
    // The simultaneous change is a setup violation only; the other change has 9.4 us of hold.
    EXPECT_EQ(r[DriverRule::DirHold].violations, 0U);
    EXPECT_EQ(r[DriverRule::DirHold].checked, 2U);
    EXPECT_EQ(*r[DriverRule::DirHold].min_ps, 9'400 * kNs);
}

TEST(MetricsDriverTiming, DirHoldViolation) {
    const std::vector<TimePs> rises = grid(10 * kUs, 10 * kUs, 3);
    const EdgeLog dir = dir_log({20 * kUs + 100 * kNs});  // 100 ns after the 20 us step
    const DriverTimingReport r = check_driver_timing(step_log(rises), dir, DriverLimits{});
    EXPECT_EQ(r[DriverRule::DirHold].violations, 1U);
    EXPECT_EQ(*r[DriverRule::DirHold].min_ps, 100 * kNs);
    EXPECT_EQ(*r[DriverRule::DirHold].first_violation_at_ps, 20 * kUs + 100 * kNs);
    EXPECT_EQ(r[DriverRule::DirSetup].violations, 0U);  // 9.9 us before the 30 us step
}

TEST(MetricsDriverTiming, StepRateAbove250kHz) {
    // 3.9 us period with 1.95 us high and low: only the rate rule fails.
    const DriverTimingReport r =
        check_driver_timing(step_log(grid(0, 3'900 * kNs, 6), 1'950 * kNs), EdgeLog{}, DriverLimits{});
    EXPECT_EQ(r[DriverRule::Rate].violations, 5U);
    EXPECT_EQ(*r[DriverRule::Rate].min_ps, 3'900 * kNs);
    EXPECT_EQ(r.total_violations(), 5U);
    EXPECT_DOUBLE_EQ(rule_limit_ns(DriverRule::Rate, DriverLimits{}), 4'000.0);
}

TEST(MetricsDriverTiming, RepeatedLevelsAreNotEdges) {
    EdgeLog step{"step_x", false, {}};
    step.add(0, true);
    step.add(1 * kUs, true);  // same level written again: no edge
    step.add(2 * kUs, false);
    const DriverTimingReport r = check_driver_timing(step, EdgeLog{}, DriverLimits{});
    EXPECT_EQ(r[DriverRule::StepHigh].checked, 1U);
    EXPECT_EQ(*r[DriverRule::StepHigh].min_ps, 2 * kUs);
}

}  // namespace
}  // namespace cnc::metrics
