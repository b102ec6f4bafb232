// The job estimate and the default simulated-time limit, against sums worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "run/job_estimate.hpp"

namespace cnc::sim {
namespace {

using geom::Segment;
using host::MotionKind;

host::ProgrammedMove line(geom::Vec2 from, geom::Vec2 to, double feed_mm_per_min,
                          MotionKind kind = MotionKind::Linear) {
    return {kind, Segment::line(from, to), feed_mm_per_min, kind != MotionKind::Rapid, 1};
}

TEST(JobEstimate, SquareAtItsFeedsWithRapidsAtTheRapidFeed) {
    // 14.14 mm rapid at 1200 mm/min (20 mm/s), four 20 mm sides at 600 mm/min (10 mm/s), the rapid back.
    const host::Program p{"sq.nc",
                          {line({0, 0}, {10, 10}, 1200, MotionKind::Rapid), line({10, 10}, {30, 10}, 600),
                           line({30, 10}, {30, 30}, 600), line({30, 30}, {10, 30}, 600), line({10, 30}, {10, 10}, 600),
                           line({10, 10}, {0, 0}, 1200, MotionKind::Rapid)}};
    const JobEstimate e = estimate_job(p, ArchPace{});
    const double expected_s = 2 * std::sqrt(200.0) / 20.0 + 4 * 2.0;
    EXPECT_NEAR(e.expected_s, expected_s, 1e-12);
    EXPECT_EQ(e.moves, 6U);
    EXPECT_NEAR(e.limit_s, 2 * expected_s + 6 + 10, 1e-12);
    EXPECT_EQ(limit_formula(e), "2 x 9.414 s + 1 s x 6 moves + 10 s");
}

TEST(JobEstimate, HostWaitsAddTheirTime) {
    // 10 mm at 600 mm/min (1 s), a 2.5 s dwell before it and a 7 s pause after it.
    host::Program p{"w.nc", {line({0, 0}, {10, 0}, 600)}};
    p.waits = {{0, 2.5, host::WaitCause::Dwell, 1}, {1, 7.0, host::WaitCause::OperatorPause, 3}};
    EXPECT_NEAR(estimate_job(p, ArchPace{}).expected_s, 10.5, 1e-12);
}

TEST(JobEstimate, ArcsByTheirArcLength) {
    // A quarter circle of radius 10 mm at 600 mm/min: 5 pi mm at 10 mm/s.
    const host::Program p{"arc.nc", {{MotionKind::ArcCCW, Segment::arc({10, 0}, {0, 10}, {0, 0}, true), 600, true, 3}}};
    EXPECT_NEAR(estimate_job(p, ArchPace{}).expected_s, M_PI / 2, 1e-9);
}

TEST(JobEstimate, AxisSpeedLimitsHoldThePathSpeed) {
    ArchPace pace;
    pace.max_speed_x_mm_per_s = 50.0;
    pace.max_speed_y_mm_per_s = 25.0;
    // F6000 is 100 mm/s: 10 mm along X at 50 mm/s, 10 mm along Y at 25 mm/s; on the diagonal each axis would
    // need 70.7 mm/s, so Y's 25 mm/s sets it: 10 mm of Y in 0.4 s.
    const host::Program x{"x.nc", {line({0, 0}, {10, 0}, 6000)}};
    const host::Program y{"y.nc", {line({0, 0}, {0, 10}, 6000)}};
    const host::Program d{"d.nc", {line({0, 0}, {10, 10}, 6000)}};
    EXPECT_NEAR(estimate_job(x, pace).expected_s, 0.2, 1e-12);
    EXPECT_NEAR(estimate_job(y, pace).expected_s, 0.4, 1e-12);
    EXPECT_NEAR(estimate_job(d, pace).expected_s, 0.4, 1e-12);
    // A feed below the limits is kept: 10 mm at 600 mm/min.
    EXPECT_NEAR(estimate_job(host::Program{"s.nc", {line({0, 0}, {10, 0}, 600)}}, pace).expected_s, 1.0, 1e-12);
    // An arc's tangent turns through both axes: the smaller limit, 25 mm/s, over 5 pi mm.
    const host::Program arc{"a.nc",
                            {{MotionKind::ArcCW, Segment::arc({10, 0}, {0, -10}, {0, 0}, false), 6000, true, 1}}};
    EXPECT_NEAR(estimate_job(arc, pace).expected_s, 5 * M_PI / 25.0, 1e-9);
}

TEST(JobEstimate, StartUpLinkAndRampsAreAdded) {
    ArchPace pace;
    pace.startup_s = 0.35;
    pace.link_s = 0.025;
    pace.ramp_s = [](double speed_mm_per_s) { return speed_mm_per_s / 100.0; };  // 100 mm/s^2 from rest
    // Two 10 mm moves at 10 mm/s: 1 s each plus 0.1 s to reach the speed and stop.
    const host::Program p{"r.nc", {line({0, 0}, {10, 0}, 600), line({10, 0}, {0, 0}, 600)}};
    const JobEstimate e = estimate_job(p, pace);
    EXPECT_NEAR(e.expected_s, 0.35 + 0.025 + 2 * 1.1, 1e-12);
    EXPECT_NEAR(e.limit_s, 2 * e.expected_s + 2 + 10, 1e-12);
}

TEST(JobEstimate, EmptyJobStillGetsTheFixedAllowance) {
    const JobEstimate e = estimate_job(host::Program{"empty.nc", {}}, ArchPace{});
    EXPECT_EQ(e.expected_s, 0.0);
    EXPECT_EQ(e.limit_s, 10.0);
}

}  // namespace
}  // namespace cnc::sim
