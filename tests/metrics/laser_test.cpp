#include <gtest/gtest.h>

#include "metrics/metrics.hpp"
#include "metrics_test_util.hpp"

namespace cnc::metrics {
namespace {

using test::kMicrostepMm;

// Move 0 cuts 100 microsteps along X at F375 (one step per ms, steps at 1..100 ms); move 1 is a rapid of
// 100 microsteps at F3750 (one step per 0.1 ms, 150.0 .. 159.9 ms). The tool is still from 100 to 150 ms.
RunInput two_moves_with_laser(std::vector<std::pair<TimePs, TimePs>> laser_on) {
    RunInput in;
    std::vector<TimePs> x;
    for (int k = 1; k <= 100; ++k) {
        x.push_back(k * kPsPerMs);
        in.tool.push_back({k * kPsPerMs, {k * kMicrostepMm, 0}});
    }
    for (int k = 0; k < 100; ++k) {
        const TimePs t = 150 * kPsPerMs + k * 100 * kPsPerUs;
        x.push_back(t);
        in.tool.push_back({t, {(101 + k) * kMicrostepMm, 0}});
    }
    in.axes.push_back(test::axis(x));
    in.moves.push_back(test::line_move(0, {0, 0}, {100 * kMicrostepMm, 0}, 375.0, 0, 100 * kPsPerMs));
    MoveSpec rapid = test::line_move(1, {100 * kMicrostepMm, 0}, {200 * kMicrostepMm, 0}, 3'750.0,
                                     149 * kPsPerMs, 160 * kPsPerMs);
    rapid.rapid = true;
    in.moves.push_back(rapid);
    EdgeLog laser{"laser", false, {}};
    for (const auto& [on, off] : laser_on) {
        laser.add(on, true);
        laser.add(off, false);
    }
    in.laser = laser;
    in.t_job_start_ps = 0;
    in.t_job_end_ps = 200 * kPsPerMs;
    return in;
}

TEST(MetricsLaser, DwellBeforeTheFirstStepAndWhileStillBetweenMoves) {
    // On from 0.5 ms to 120 ms: 0.5 ms before the first step, then 20 ms of the 50 ms pause.
    const RunMetrics m = compute_metrics(two_moves_with_laser({{500 * kPsPerUs, 120 * kPsPerMs}}));
    ASSERT_TRUE(m.laser);
    EXPECT_DOUBLE_EQ(m.laser->on_ms, 119.5);
    EXPECT_NEAR(*m.laser->dwell_ms, 20.5, 1e-9);
    EXPECT_EQ(m.laser->dwell_intervals, 2U);
    EXPECT_NEAR(*m.laser->dwell_longest_ms, 20.0, 1e-9);
    EXPECT_NEAR(*m.laser->dwell_longest_at_s, 0.100, 1e-12);
    EXPECT_DOUBLE_EQ(*m.laser->on_in_rapid_ms, 0.0);
}

TEST(MetricsLaser, OnDuringARapidIsReportedAndIsNotDwell) {
    // On from 155 to 157 ms, in the middle of the rapid's motion; also on after the last step (still).
    const RunMetrics m =
        compute_metrics(two_moves_with_laser({{155 * kPsPerMs, 157 * kPsPerMs}, {170 * kPsPerMs, 171 * kPsPerMs}}));
    EXPECT_NEAR(*m.laser->on_in_rapid_ms, 2.0, 1e-9);
    EXPECT_NEAR(*m.laser->dwell_ms, 1.0, 1e-9);
    EXPECT_NEAR(m.laser->on_ms, 3.0, 1e-9);
}

TEST(MetricsLaser, CrawlingBelowTenPercentOfFIsDwell) {
    // A cutting move at F375 whose steps come every 20 ms (5 % of F) while the laser is on.
    RunInput in;
    std::vector<TimePs> x;
    for (int k = 0; k < 5; ++k) {
        x.push_back(k * 20 * kPsPerMs);
        in.tool.push_back({k * 20 * kPsPerMs, {k * kMicrostepMm, 0}});
    }
    in.axes.push_back(test::axis(x));
    in.moves.push_back(test::line_move(0, {0, 0}, {4 * kMicrostepMm, 0}, 375.0, 0, 80 * kPsPerMs));
    in.laser = EdgeLog{"laser", true, {}};  // on for the whole job
    in.t_job_end_ps = 80 * kPsPerMs;
    const RunMetrics m = compute_metrics(in);
    EXPECT_NEAR(*m.laser->dwell_ms, 80.0, 1e-9);
    EXPECT_EQ(m.laser->dwell_intervals, 1U);
}

TEST(MetricsLaser, AbsentLaserGivesNoLaserMetrics) {
    RunInput in = two_moves_with_laser({});
    in.laser.reset();
    EXPECT_FALSE(compute_metrics(in).laser.has_value());
}

}  // namespace
}  // namespace cnc::metrics
