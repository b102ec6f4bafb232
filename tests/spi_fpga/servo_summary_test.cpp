// The servo periods' summary (models/host/servo/core/servo_summary.hpp), folded period by period: counts by mode,
// the wake-up latency's extremes and mean, the staircase excerpt's first running word and its row limit.
#include <gtest/gtest.h>

#include <cstdint>

#include "host/servo/core/servo_summary.hpp"

using cnc::kPsPerUs;
using cnc::TimePs;
using namespace cnc::host::servo;

namespace {

PeriodRecord period(PeriodMode mode, std::uint32_t x_period_cycles, double x_steps_per_s) {
    PeriodRecord r;
    r.mode = mode;
    r.axes[0].word.period_cycles = x_period_cycles;
    r.axes[0].requested_steps_per_s = x_steps_per_s;
    return r;
}

}  // namespace

TEST(ServoSummary, EmptyHasNoPeriodsAndZeroLatency) {
    const ServoSummary s;
    EXPECT_EQ(s.periods(), 0U);
    EXPECT_EQ(s.latency_mean_ps(), 0.0);
    EXPECT_TRUE(s.staircase().empty());
}

TEST(ServoSummary, CountsModesAndLatencyExtremes) {
    ServoSummary s;
    // latencies 30, 10, 20 us: min 10, max 30, mean 20 us; modes Track, Track, Land, then Done (counted in
    // the periods, in neither mode)
    s.add(period(PeriodMode::Track, 0, 0.0), {1000 * kPsPerUs + 30 * kPsPerUs, 30 * kPsPerUs});
    s.add(period(PeriodMode::Track, 0, 0.0), {2000 * kPsPerUs + 10 * kPsPerUs, 10 * kPsPerUs});
    s.add(period(PeriodMode::Land, 0, 0.0), {3000 * kPsPerUs + 20 * kPsPerUs, 20 * kPsPerUs});
    s.add(period(PeriodMode::Done, 0, 0.0), {4000 * kPsPerUs + 20 * kPsPerUs, 20 * kPsPerUs});
    EXPECT_EQ(s.periods(), 4U);
    EXPECT_EQ(s.tracking_periods(), 2U);
    EXPECT_EQ(s.landing_periods(), 1U);
    EXPECT_EQ(s.latency_min_ps(), 10 * kPsPerUs);
    EXPECT_EQ(s.latency_max_ps(), 30 * kPsPerUs);
    EXPECT_EQ(s.latency_mean_ps(), 20.0 * kPsPerUs);  // (30 + 10 + 20 + 20) / 4
}

TEST(ServoSummary, StaircaseStartsAtTheFirstRunningWordAndKeepsTwelveRows) {
    ServoSummary s;
    s.add(period(PeriodMode::Track, 0, 0.0), {0, 0});  // stopped: before the staircase
    for (std::uint32_t n = 1; n <= 20; ++n) {
        // a stopped word after the first running one stays in the excerpt
        const std::uint32_t word = n == 3 ? 0 : 1000 * n;
        s.add(period(PeriodMode::Track, word, 10.0 * n), {static_cast<TimePs>(n) * 1000 * kPsPerUs, 0});
    }
    ASSERT_EQ(s.staircase().size(), ServoSummary::kStaircaseRows);
    EXPECT_EQ(s.staircase().front().t_ps, 1000 * kPsPerUs);
    EXPECT_EQ(s.staircase().front().word[0].period_cycles, 1000U);
    EXPECT_EQ(s.staircase()[2].word[0].period_cycles, 0U);
    EXPECT_EQ(s.staircase().back().t_ps, 12'000 * kPsPerUs);
    EXPECT_EQ(s.staircase().back().requested_steps_per_s[0], 120.0);
}
