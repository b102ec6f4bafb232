#include <gtest/gtest.h>

#include <cmath>

#include "metrics/metrics.hpp"
#include "metrics/pulse/pulse_runs.hpp"
#include "metrics_test_util.hpp"

namespace cnc::metrics {
namespace {

using test::grid;
using test::kFpgaClockPs;

constexpr TimePs kPeriod3200HzPs = 15'625 * kFpgaClockPs;  // seed 000: 15,625 clocks = 312.5 us

TEST(MetricsPulseRuns, ExactFpgaPeriodHasZeroJitterAndSubPicosecondTie) {
    // 15,889 edges at exactly 312.5 us (about 5 s), starting late in a job: the FPGA must score 0.
    RunInput in;
    in.axes.push_back(test::axis(grid(1'000 * kPsPerSec, kPeriod3200HzPs, 15'889)));
    const RunMetrics m = compute_metrics(in);
    ASSERT_EQ(m.axes[0].runs.size(), 1U);
    const PulseRun& run = m.axes[0].runs[0];
    EXPECT_EQ(run.edges(), 15'889U);
    EXPECT_EQ(run.period->std_ns, 0.0);
    EXPECT_EQ(run.period->pp_ns, 0.0);
    EXPECT_DOUBLE_EQ(run.period->mean_ns, 312'500.0);
    EXPECT_LT(run.tie->max_abs_ns, 1e-3);
    EXPECT_LT(run.tie->rms_ns, 1e-3);
    EXPECT_NEAR(run.tie->period_ns, 312'500.0, 1e-6);
    EXPECT_NEAR(*run.rate_achieved_steps_per_s, 3'200.0, 1e-9);
    EXPECT_FALSE(run.rate_error_pct.has_value());  // analyze: nothing commanded
}

TEST(MetricsPulseRuns, OneClockPerturbationGivesTheLeastSquaresResidual) {
    // Edge 500 of 1001 one clock (20 ns) late. For a single impulse d at the centre of the fit, the
    // residual there is d (1 - 1/n) and the RMS is d sqrt((1 - 1/n) / n); two periods change by +-d.
    std::vector<TimePs> t = grid(0, kPeriod3200HzPs, 1001);
    t[500] += kFpgaClockPs;
    const double d_ns = 20.0;
    const double n = 1001.0;
    const auto tie = tie_stats(t.data(), t.size());
    ASSERT_TRUE(tie);
    EXPECT_NEAR(tie->max_abs_ns, d_ns * (1.0 - 1.0 / n), 1e-6);
    EXPECT_NEAR(tie->rms_ns, d_ns * std::sqrt((1.0 - 1.0 / n) / n), 1e-6);
    const auto period = period_stats(t.data(), t.size());
    ASSERT_TRUE(period);
    EXPECT_DOUBLE_EQ(period->pp_ns, 40.0);
    EXPECT_NEAR(period->std_ns, d_ns * std::sqrt(2.0 / 1000.0), 1e-9);
}

TEST(MetricsPulseRuns, TieOfEachEdgeIsItsResidualAgainstTheFittedGrid) {
    // The same centred impulse: it leaves the fitted slope alone (the fit is symmetric about the centre) and lifts
    // the intercept by d/n, so edge 500 is d (1 - 1/n) late and every other edge d/n early.
    std::vector<TimePs> t = grid(0, kPeriod3200HzPs, 1001);
    t[500] += kFpgaClockPs;
    const double d_ns = 20.0;
    const double n = 1001.0;
    const std::vector<double> tie = tie_residuals_ns(t.data(), t.size());
    ASSERT_EQ(tie.size(), t.size());
    for (std::size_t k = 0; k < tie.size(); ++k) {
        EXPECT_NEAR(tie[k], k == 500 ? d_ns * (1.0 - 1.0 / n) : -d_ns / n, 1e-6) << k;
    }
    EXPECT_TRUE(tie_residuals_ns(t.data(), 2).empty());
}

TEST(MetricsPulseRuns, TieNeedsThreeEdgesAndPeriodsTwo) {
    const std::vector<TimePs> t = grid(0, 1'000'000, 2);
    EXPECT_FALSE(tie_stats(t.data(), 2).has_value());
    EXPECT_TRUE(period_stats(t.data(), 2).has_value());
    EXPECT_FALSE(period_stats(t.data(), 1).has_value());
}

TEST(MetricsPulseRuns, RateErrorPerMoveIsSignedPercentOfCommandedRate) {
    // Move 0: 3200 Hz commanded, period 312,520 ns (slower); move 1: 3200 Hz commanded, 312,480 ns.
    RunInput in;
    std::vector<TimePs> t = grid(0, 312'520'000, 100);
    const std::vector<TimePs> t1 = grid(50 * kPsPerMs, 312'480'000, 100);
    t.insert(t.end(), t1.begin(), t1.end());
    in.axes.push_back(test::axis(t));
    for (int i = 0; i < 2; ++i) {
        MoveSpec m = test::line_move(i, {}, {}, 600.0, i * 50 * kPsPerMs, (i + 1) * 50 * kPsPerMs);
        m.rate_steps_per_s = {3'200.0, 0.0};
        in.moves.push_back(m);
    }
    const RunMetrics m = compute_metrics(in);
    ASSERT_EQ(m.axes[0].runs.size(), 2U);
    EXPECT_NEAR(*m.axes[0].runs[0].rate_error_pct, (312'500.0 / 312'520.0 - 1.0) * 100.0, 1e-9);
    EXPECT_NEAR(*m.axes[0].runs[1].rate_error_pct, (312'500.0 / 312'480.0 - 1.0) * 100.0, 1e-9);
    EXPECT_LT(*m.axes[0].runs[0].rate_error_pct, 0.0);
    EXPECT_GT(*m.axes[0].runs[1].rate_error_pct, 0.0);
    // The worst (largest magnitude) keeps its sign: the faster run is off by slightly more.
    EXPECT_NEAR(*m.pulse.rate_error_worst_pct, (312'500.0 / 312'480.0 - 1.0) * 100.0, 1e-9);
}

TEST(MetricsPulseRuns, MoveAttributionPutsBoundaryEdgesInTheLaterMoveAndCountsEarlyEdges) {
    RunInput in;
    constexpr TimePs kMs = kPsPerMs;
    in.axes.push_back(test::axis({5 * kMs, 100 * kMs, 200 * kMs, 300 * kMs, 400 * kMs}));
    in.moves.push_back(test::line_move(0, {}, {}, 600.0, 100 * kMs, 300 * kMs));
    in.moves.push_back(test::line_move(1, {}, {}, 600.0, 300 * kMs, 500 * kMs));
    const RunMetrics m = compute_metrics(in);
    EXPECT_EQ(m.axes[0].unattributed_edges, 1U);
    ASSERT_EQ(m.axes[0].runs.size(), 2U);
    EXPECT_EQ(m.axes[0].runs[0].edges(), 2U);  // 100, 200
    EXPECT_EQ(m.axes[0].runs[1].edges(), 2U);  // 300 (on the boundary), 400
    EXPECT_EQ(m.axes[0].runs[1].t_first_ps, 300 * kMs);
}

TEST(MetricsPulseRuns, AnalyzeSplitsOnRateChangePauseAndDirChange) {
    std::vector<TimePs> t = grid(0, 300'000'000, 10);  // run 0: 300 us
    const auto add = [&](TimePs period, std::size_t n, TimePs after) {
        const std::vector<TimePs> more = grid(t.back() + after, period, n);
        t.insert(t.end(), more.begin(), more.end());
    };
    add(200'000'000, 10, 200'000'000);  // run 1: 200 us, back to back (rate change)
    add(200'000'000, 10, 400'000'000);  // run 2: same rate after a pause of 2 periods
    add(200'000'000, 10, 200'000'000);  // run 3: after a DIR change
    const TimePs dir_change = t[29] + 100'000'000;
    const std::vector<EdgeRange> runs = split_runs(t, {dir_change}, 0.005);
    ASSERT_EQ(runs.size(), 4U);
    EXPECT_EQ(runs[0].begin, 0U);
    EXPECT_EQ(runs[0].end, 10U);
    EXPECT_EQ(runs[1].end, 20U);
    EXPECT_EQ(runs[2].end, 30U);
    EXPECT_EQ(runs[3].end, 40U);
}

TEST(MetricsPulseRuns, AnalyzeKeepsARunWhosePeriodsWanderInsideTheTolerance) {
    // Periods alternate 312.5 us +- 0.2 % (0.4 % apart): one run at tolerance 0.5 %, many at 0.1 %.
    std::vector<TimePs> t{0};
    for (int k = 0; k < 50; ++k) t.push_back(t.back() + (k % 2 == 0 ? 313'125'000 : 311'875'000));
    EXPECT_EQ(split_runs(t, {}, 0.005).size(), 1U);
    EXPECT_GT(split_runs(t, {}, 0.001).size(), 10U);
}

TEST(MetricsPulseRuns, SummaryPicksTheWorstRunPerAxis) {
    RunInput in;
    std::vector<TimePs> t = grid(0, kPeriod3200HzPs, 101);
    t[50] += kFpgaClockPs;
    std::vector<TimePs> t2 = grid(100 * kPsPerMs, kPeriod3200HzPs, 101);
    t.insert(t.end(), t2.begin(), t2.end());
    in.axes.push_back(test::axis(t));
    in.moves.push_back(test::line_move(0, {}, {}, 600.0, 0, 50 * kPsPerMs));
    in.moves.push_back(test::line_move(1, {}, {}, 600.0, 100 * kPsPerMs, 150 * kPsPerMs));
    const RunMetrics m = compute_metrics(in);
    const AxisPulseSummary& s = m.axes[0].pulse;
    EXPECT_EQ(s.runs, 2U);
    EXPECT_EQ(s.runs_measured, 2U);
    EXPECT_EQ(*s.worst_tie_run, 0U);
    EXPECT_EQ(*s.worst_jitter_run, 0U);
    EXPECT_DOUBLE_EQ(*s.jitter_pp_max_ns, 40.0);
    EXPECT_NEAR(*s.tie_max_ns, 20.0 * (1.0 - 1.0 / 101.0), 1e-6);
    EXPECT_NEAR(*s.tie_max_period_frac, 20.0 * (1.0 - 1.0 / 101.0) / 312'500.0, 1e-12);
    EXPECT_DOUBLE_EQ(*m.pulse.tie_max_ns, *s.tie_max_ns);
}

}  // namespace
}  // namespace cnc::metrics
