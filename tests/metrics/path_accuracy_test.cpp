#include <gtest/gtest.h>

#include <cmath>

#include "metrics/metrics.hpp"
#include "metrics_test_util.hpp"

namespace cnc::metrics {
namespace {

using test::kMicrostepMm;

TEST(MetricsPathAccuracy, StaircaseAlongA45DegreeLine) {
    // X and Y alternate single microsteps along y = x: every other sample sits d / sqrt(2) off the line.
    constexpr int kSteps = 100;
    const double d = kMicrostepMm;
    RunInput in;
    in.moves.push_back(test::line_move(0, {0, 0}, {kSteps * d, kSteps * d}, 600.0, 0, 10 * kPsPerMs));
    in.tool.push_back({0, {0, 0}});
    for (int k = 0; k < kSteps; ++k) {
        const TimePs t = (2 * k + 1) * 50 * kPsPerUs;
        in.tool.push_back({t, {(k + 1) * d, k * d}});
        in.tool.push_back({t + 50 * kPsPerUs, {(k + 1) * d, (k + 1) * d}});
    }
    const RunMetrics m = compute_metrics(in);
    const double off_um = d / std::sqrt(2.0) * 1000.0;  // 4.419 um
    EXPECT_NEAR(*m.path.contour_max_um, off_um, 1e-9);
    EXPECT_NEAR(*m.path.contour_rms_um, off_um * std::sqrt(double(kSteps) / (2 * kSteps + 1)), 1e-9);
    EXPECT_NEAR(*m.moves[0].path.contour_max_um, off_um, 1e-9);
    EXPECT_EQ(m.path.samples, 2U * kSteps + 1);
    EXPECT_NEAR(*m.path.endpoint_vs_command_max_um, 0.0, 1e-9);
    EXPECT_NEAR(*m.path.job_end_um, 0.0, 1e-9);
}

TEST(MetricsPathAccuracy, FollowingErrorOfAConstantLag) {
    // Programmed: (0,0) -> (1,0) mm at F600 = 10 mm/s from the first step edge at 1 ms. The tool is at
    // k microsteps 100 us later than programmed: following error = 10 mm/s * 100 us = 1 um; at the end
    // both are at the end point.
    constexpr int kSteps = 160;
    const TimePs t0 = kPsPerMs;
    const TimePs period = 625 * kPsPerUs;  // 1/160 mm at 10 mm/s
    RunInput in;
    std::vector<TimePs> rises;
    for (int k = 1; k <= kSteps; ++k) rises.push_back(t0 + (k - 1) * period);
    in.axes.push_back(test::axis(rises));
    in.moves.push_back(test::line_move(0, {0, 0}, {1, 0}, 600.0, 0, t0 + kSteps * period));
    for (int k = 1; k <= kSteps; ++k) in.tool.push_back({t0 + k * period + 100 * kPsPerUs, {k * kMicrostepMm, 0}});
    const RunMetrics m = compute_metrics(in);
    EXPECT_NEAR(*m.moves[0].path.following_max_um, 1.0, 1e-6);
    EXPECT_NEAR(*m.path.following_max_um, 1.0, 1e-6);
    // All but the last sample lag by 1 um; the last is past the programmed end time (clamped): 0.
    EXPECT_NEAR(*m.path.following_rms_um, std::sqrt((kSteps - 1.0) / kSteps), 1e-6);
    EXPECT_NEAR(*m.path.contour_max_um, 0.0, 1e-9);
}

TEST(MetricsPathAccuracy, EndpointErrorAgainstCommandAndAgainstProgram) {
    // Two chords of one programmed arc; the second ends 3/4 um off its commanded end, and the commanded
    // end is itself quantised 2 um away from the programmed arc end.
    const geom::Segment arc = geom::Segment::arc({1, 0}, {0, 1}, {0, 0}, true);
    const geom::Vec2 mid{std::sqrt(0.5), std::sqrt(0.5)};
    RunInput in;
    MoveSpec a = test::line_move(0, {1, 0}, mid, 600.0, 0, 10 * kPsPerMs);
    MoveSpec b = test::line_move(1, mid, {0.002, 1.0}, 600.0, 10 * kPsPerMs, 20 * kPsPerMs);
    a.path = arc;
    b.path = arc;
    a.programmed = b.programmed = 0;
    in.moves = {a, b};
    in.tool = {{5 * kPsPerMs, mid}, {20 * kPsPerMs, {0.002 + 0.0003, 1.0 + 0.0004}}, {25 * kPsPerMs, {0, 1}}};
    const RunMetrics m = compute_metrics(in);
    EXPECT_NEAR(*m.pieces[0].path.endpoint_vs_command_um, 0.0, 1e-9);
    EXPECT_FALSE(m.pieces[0].path.endpoint_vs_program_um.has_value());  // not the last chord of the arc
    EXPECT_NEAR(*m.pieces[1].path.endpoint_vs_command_um, 0.5, 1e-9);
    EXPECT_NEAR(*m.pieces[1].path.endpoint_vs_program_um, std::hypot(2.3, 0.4), 1e-6);
    // The programmed move: the worst of its chords against their ends, its last chord against the program.
    ASSERT_EQ(m.moves.size(), 1U);
    EXPECT_EQ(m.moves[0].pieces, 2U);
    EXPECT_NEAR(*m.moves[0].path.endpoint_vs_command_um, 0.5, 1e-9);
    EXPECT_NEAR(*m.moves[0].path.endpoint_vs_program_um, std::hypot(2.3, 0.4), 1e-6);
    EXPECT_NEAR(*m.path.endpoint_vs_program_max_um, std::hypot(2.3, 0.4), 1e-6);
    EXPECT_NEAR(*m.path.job_end_um, 0.0, 1e-9);  // the last sample is back on the arc end
}

TEST(MetricsPathAccuracy, ContourUsesTheNeighbouringMovesNearACorner) {
    // A sample taken just after the corner of an L while the first leg is still active is on the second leg.
    RunInput in;
    in.moves.push_back(test::line_move(0, {0, 0}, {1, 0}, 600.0, 0, 10 * kPsPerMs));
    in.moves.push_back(test::line_move(1, {1, 0}, {1, 1}, 600.0, 10 * kPsPerMs, 20 * kPsPerMs));
    in.tool = {{9 * kPsPerMs, {1, 0.5}}};
    const RunMetrics m = compute_metrics(in);
    EXPECT_NEAR(*m.path.contour_max_um, 0.0, 1e-9);
}

TEST(MetricsPathAccuracy, ContourOfALaggingToolUsesThePreviousMove) {
    // The carriage lags: just after the second leg became active the tool is still on the first leg, 0.5 mm from
    // the second: on the programmed path all the same.
    RunInput in;
    in.moves.push_back(test::line_move(0, {0, 0}, {1, 0}, 600.0, 0, 10 * kPsPerMs));
    in.moves.push_back(test::line_move(1, {1, 0}, {1, 1}, 600.0, 10 * kPsPerMs, 20 * kPsPerMs));
    in.tool = {{11 * kPsPerMs, {0.5, 0}}};
    const RunMetrics m = compute_metrics(in);
    EXPECT_NEAR(*m.path.contour_max_um, 0.0, 1e-9);
    EXPECT_NEAR(*m.moves[1].path.contour_max_um, 0.0, 1e-9);
}

TEST(MetricsPathAccuracy, NothingWithoutToolSamples) {
    RunInput in;
    in.moves.push_back(test::line_move(0, {0, 0}, {1, 0}, 600.0, 0, 10 * kPsPerMs));
    const RunMetrics m = compute_metrics(in);
    EXPECT_FALSE(m.path.contour_max_um.has_value());
    EXPECT_FALSE(m.moves[0].path.endpoint_vs_command_um.has_value());
}

}  // namespace
}  // namespace cnc::metrics
