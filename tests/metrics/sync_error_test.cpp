#include <gtest/gtest.h>

#include "metrics/metrics.hpp"
#include "metrics_test_util.hpp"

namespace cnc::metrics {
namespace {

using test::grid;

TEST(MetricsSyncError, TruncatedSubordinatePeriodDriftsOneDeltaPerStep) {
    // X commanded 6400 Hz and running at exactly 156.25 us; Y commanded 3200 Hz but running at
    // 312,520 ns, 20 ns (one FPGA clock) longer than 312.5 us. Y's step k is k * 20 ns late, so the
    // last of its 100 steps is 99 * 20 ns = 1980 ns late; TIE sees nothing of this.
    const TimePs t0 = 7 * kPsPerMs;
    RunInput in;
    in.axes.push_back(test::axis(grid(t0, 156'250'000, 200), "x"));
    in.axes.push_back(test::axis(grid(t0, 312'520'000, 100), "y"));
    MoveSpec move = test::line_move(0, {}, {}, 600.0, t0 - kPsPerMs, t0 + 40 * kPsPerMs);
    move.rate_steps_per_s = {6'400.0, 3'200.0};
    in.moves.push_back(move);
    const RunMetrics m = compute_metrics(in);
    ASSERT_EQ(m.moves.size(), 1U);
    EXPECT_NEAR(*m.moves[0].sync_max_abs_ns[0], 0.0, 1e-6);
    EXPECT_NEAR(*m.moves[0].sync_max_abs_ns[1], 99 * 20.0, 1e-6);
    EXPECT_NEAR(*m.axes[1].sync_max_abs_ns, 1980.0, 1e-6);
    EXPECT_NEAR(*m.pulse.sync_max_abs_ns, 1980.0, 1e-6);
    EXPECT_LT(*m.axes[1].pulse.tie_max_ns, 1e-3);
}

TEST(MetricsSyncError, ReferenceIsTheFirstEdgeOfTheMoveOnAnyAxis) {
    // Y starts 1 us after X: every Y edge is 1 us late against the move's start.
    const TimePs t0 = kPsPerMs;
    RunInput in;
    in.axes.push_back(test::axis(grid(t0, 100 * kPsPerUs, 10), "x"));
    in.axes.push_back(test::axis(grid(t0 + kPsPerUs, 200 * kPsPerUs, 5), "y"));
    MoveSpec move = test::line_move(0, {}, {}, 600.0, 0, 3 * kPsPerMs);
    move.rate_steps_per_s = {10'000.0, 5'000.0};
    in.moves.push_back(move);
    const RunMetrics m = compute_metrics(in);
    EXPECT_NEAR(*m.moves[0].sync_max_abs_ns[1], 1'000.0, 1e-6);
}

TEST(MetricsSyncError, AxisWithoutCommandedRateOrMovesHasNone) {
    RunInput in;
    in.axes.push_back(test::axis(grid(0, 100 * kPsPerUs, 10), "x"));
    RunMetrics m = compute_metrics(in);
    EXPECT_FALSE(m.pulse.sync_max_abs_ns.has_value());
    in.moves.push_back(test::line_move(0, {}, {}, 600.0, 0, kPsPerMs));  // rate 0 commanded
    m = compute_metrics(in);
    EXPECT_FALSE(m.moves[0].sync_max_abs_ns[0].has_value());
}

}  // namespace
}  // namespace cnc::metrics
