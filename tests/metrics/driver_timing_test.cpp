#include <gtest/gtest.h>

#include "metrics/pulse/driver_timing.hpp"
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
    step.add(12 * kUs, false);  // 2 us, fine
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

// The edges of `log` in [from_ps, to_ps).
std::vector<Edge> window(const EdgeLog& log, TimePs from_ps, TimePs to_ps) {
    std::vector<Edge> out;
    for (const Edge& e : log.edges) {
        if (e.t_ps >= from_ps && e.t_ps < to_ps) out.push_back(e);
    }
    return out;
}

TEST(MetricsDriverTiming, WindowsCutThroughAPulseAndAtASimultaneousChangeCheckAsOneTrace) {
    // The trace of DirSetupViolationsIncludingASimultaneousChange: rises at 10, 20, 30, 40 us, 2 us high; DIR
    // 600 ns before the 20 us rise and exactly at the 40 us rise. Cuts at 21 us (inside the 20 us pulse: its
    // high time and the next low time span two windows) and at 40 us (the tied DIR change and rise open the
    // last window together).
    const EdgeLog step = step_log(grid(10 * kUs, 10 * kUs, 4));
    const EdgeLog dir = dir_log({20 * kUs - 600 * kNs, 40 * kUs});
    DriverTimingStream stream(DriverLimits{}, step.initial, dir.initial);
    const std::vector<TimePs> cuts{0, 21 * kUs, 40 * kUs, 100 * kUs};
    for (std::size_t w = 0; w + 1 < cuts.size(); ++w) {
        stream.add(window(step, cuts[w], cuts[w + 1]), window(dir, cuts[w], cuts[w + 1]));
    }
    const DriverTimingReport r = stream.report();
    // Every pulse 2 us high, 8 us low, 10 us apart: no width or rate violation, the cut pulse included.
    EXPECT_EQ(r[DriverRule::StepHigh].checked, 4U);
    EXPECT_EQ(*r[DriverRule::StepHigh].min_ps, 2 * kUs);
    EXPECT_EQ(r[DriverRule::StepLow].checked, 3U);
    EXPECT_EQ(*r[DriverRule::StepLow].min_ps, 8 * kUs);
    EXPECT_EQ(r[DriverRule::Rate].checked, 3U);
    EXPECT_EQ(*r[DriverRule::Rate].min_ps, 10 * kUs);
    // Setup 600 ns and 0 (DIR first at the tie), holds 9.4 us and none at the tie: as in the one-trace test.
    EXPECT_EQ(r[DriverRule::DirSetup].violations, 2U);
    EXPECT_EQ(*r[DriverRule::DirSetup].min_ps, 0);
    EXPECT_EQ(*r[DriverRule::DirSetup].first_violation_at_ps, 20 * kUs);
    EXPECT_EQ(r[DriverRule::DirHold].violations, 0U);
    EXPECT_EQ(r[DriverRule::DirHold].checked, 2U);
    EXPECT_EQ(*r[DriverRule::DirHold].min_ps, 9'400 * kNs);
    EXPECT_EQ(r.total_violations(), 2U);
}

}  // namespace
}  // namespace cnc::metrics
