#include <gtest/gtest.h>

#include <limits>

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
    MoveSpec rapid =
        test::line_move(1, {100 * kMicrostepMm, 0}, {200 * kMicrostepMm, 0}, 3'750.0, 149 * kPsPerMs, 160 * kPsPerMs);
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

// Laser on 10..60 and 70..90 ms of a 100 ms job, a rapid moving 40..75 ms, the tool slow 0..20, 30..55 and from
// 80 ms on. By hand: on 50 + 20 = 70 ms; on in the rapid 40..60 and 70..75 = 25 ms; dwell (on and slow) 10..20,
// 30..55 and 80..90 = 45 ms in 3 stretches, the longest 25 ms from 30 ms. Folded in windows cut at 35 and 52 ms,
// inside the longest dwell stretch and the rapid, with the slow stretch 30..55 handed over as two touching parts
// (as the streaming metrics drop the part they have read), the figures are the same.
TEST(MetricsLaser, FoldedInWindowsEqualsTheWholeJob) {
    constexpr TimePs kMs = kPsPerMs;
    constexpr TimePs kForever = std::numeric_limits<TimePs>::max();
    EdgeLog laser{"laser", false, {}};
    for (const TimePs t : {10, 60, 70, 90}) laser.add(t * kMs, t == 10 || t == 70);
    const std::vector<TimeInterval> rapid{{40 * kMs, 75 * kMs}};
    const std::vector<TimeInterval> slow{{0, 20 * kMs}, {30 * kMs, 55 * kMs}, {80 * kMs, kForever}};
    const LaserResult whole = laser_result(laser, 0, 100 * kMs, rapid, slow);

    LaserFold fold(0);
    EdgeLog rest = laser;
    const std::vector<TimeInterval> slow_1{{0, 20 * kMs}, {30 * kMs, 50 * kMs}};
    fold.fold(rest.take_before(35 * kMs), rapid, &slow_1, 35 * kMs);
    const std::vector<TimeInterval> slow_2{{30 * kMs, 50 * kMs}, {50 * kMs, 55 * kMs}};
    fold.fold(rest.take_before(52 * kMs), rapid, &slow_2, 52 * kMs);
    const std::vector<TimeInterval> slow_3{{50 * kMs, 55 * kMs}, {80 * kMs, kForever}};
    const LaserResult folded = fold.finish(rest, 100 * kMs, rapid, slow_3);

    for (const LaserResult& r : {whole, folded}) {
        EXPECT_DOUBLE_EQ(r.on_ms, 70.0);
        EXPECT_DOUBLE_EQ(*r.on_in_rapid_ms, 25.0);
        EXPECT_DOUBLE_EQ(*r.dwell_ms, 45.0);
        EXPECT_EQ(r.dwell_intervals, 3U);
        EXPECT_DOUBLE_EQ(*r.dwell_longest_ms, 25.0);
        EXPECT_DOUBLE_EQ(*r.dwell_longest_at_s, 0.030);
    }
}

}  // namespace
}  // namespace cnc::metrics
