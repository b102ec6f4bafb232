#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdint>

#include "common/bad_input.hpp"
#include "common/clock_grid.hpp"

using cnc::ClockDeviation;
using cnc::ClockGrid;
using cnc::TimePs;
using cnc::cycles_to_ps;
using cnc::kJitterCutSigmas;

TEST(ClockGrid, IdealClockIsTheWholePicosecondGrid) {
    const ClockGrid g(50'000'000, {});
    EXPECT_EQ(g.hz(), 50'000'000);
    EXPECT_EQ(g.at(0), 0);
    EXPECT_EQ(g.at(1), 20'000);
    EXPECT_EQ(g.at(123'456'789), 123'456'789LL * 20'000);
    EXPECT_EQ(g.last_at_or_before(39'999), 1);
    EXPECT_EQ(g.last_at_or_before(40'000), 2);
    EXPECT_EQ(g.first_after(40'000), 3);
    EXPECT_EQ(g.first_at_or_after(40'000), 2);
    EXPECT_EQ(g.first_at_or_after(40'001), 3);
    EXPECT_EQ(g.last_at_or_before(-1), -1);
    EXPECT_EQ(g.at(g.last_at_or_before(60'000)), 60'000);  // an edge
    EXPECT_NE(g.at(g.last_at_or_before(60'001)), 60'001);  // between edges
    EXPECT_EQ(g.grid_hz(), 50'000'000);
}

TEST(ClockGrid, OffsetScalesEveryPeriod) {
    // +100 ppm on 50 MHz is 50 005 000 Hz: after 50 005 000 edges exactly one second has passed, 100 us before
    // the nominal clock's 50 005 000th edge at 1.0001 s.
    const ClockGrid g(50'000'000, {100.0, 0.0, 1});
    EXPECT_EQ(g.hz(), 50'005'000);
    EXPECT_DOUBLE_EQ(g.offset_ppm(), 100.0);
    EXPECT_EQ(g.at(50'005'000), cnc::kPsPerSec);
    EXPECT_EQ(g.grid_hz(), cnc::kPsPerSec);               // 1e12 / 50 005 000 is not a whole picosecond
    const ClockGrid slow(16'000'000, {-5000.0, 0.0, 1});  // the -0.5 % end of a ceramic resonator's tolerance
    EXPECT_EQ(slow.hz(), 15'920'000);
    EXPECT_EQ(slow.at(15'920'000), cnc::kPsPerSec);
}

TEST(ClockGrid, OffsetIsRoundedToTheNearestHertz) {
    const ClockGrid g(16'000'000, {12.34, 0.0, 1});  // 16 000 197.44 Hz
    EXPECT_EQ(g.hz(), 16'000'197);
    EXPECT_NEAR(g.offset_ppm(), 12.3125, 1e-9);
}

TEST(ClockGrid, JitterHasTheAskedRmsZeroMeanAndNoMemory) {
    constexpr double kRmsPs = 50.0;
    const ClockGrid g(50'000'000, {0.0, kRmsPs, 7});
    constexpr int kEdges = 200'000;
    double sum = 0.0, sum_sq = 0.0, lag1 = 0.0, worst = 0.0;
    double prev = 0.0;
    for (std::int64_t n = 1; n <= kEdges; ++n) {
        const auto j = static_cast<double>(g.at(n) - n * 20'000);
        EXPECT_EQ(static_cast<double>(g.jitter_ps(n)), j);
        sum += j;
        sum_sq += j * j;
        lag1 += j * prev;
        worst = std::max(worst, std::fabs(j));
        prev = j;
    }
    const double mean = sum / kEdges;
    const double rms = std::sqrt(sum_sq / kEdges);
    // Standard error of the mean: 50 / sqrt(2e5) = 0.11 ps; of the rms about 0.08 ps; rounding adds 1/12 ps^2.
    EXPECT_NEAR(mean, 0.0, 0.6);
    EXPECT_NEAR(rms, std::sqrt(kRmsPs * kRmsPs + 1.0 / 12.0), 0.6);
    EXPECT_LT(std::fabs(lag1 / sum_sq), 0.02);  // white: no correlation between neighbouring edges
    EXPECT_LE(worst, cnc::kJitterCutSigmas * kRmsPs + 0.5);
    EXPECT_GT(worst, 3.5 * kRmsPs);  // a Gaussian's tail: 2e5 draws reach past 3.5 sigma
    const ClockGrid jittered(50'000'000, {0.0, 1.0, 1});
    EXPECT_EQ(jittered.grid_hz(), cnc::kPsPerSec);
}

TEST(ClockGrid, TheSameSeedGivesTheSameEdges) {
    const ClockGrid a(16'000'000, {0.0, 20.0, 42});
    const ClockGrid b(16'000'000, {0.0, 20.0, 42});
    const ClockGrid c(16'000'000, {0.0, 20.0, 43});
    int differ = 0;
    for (std::int64_t n = 0; n < 1000; ++n) {
        EXPECT_EQ(a.at(n), b.at(n));
        differ += a.at(n) != c.at(n) ? 1 : 0;
    }
    EXPECT_GT(differ, 900);
    EXPECT_EQ(a.at(0), 0);
}

TEST(ClockGrid, InverseFindsTheEdgeAroundAnyTime) {
    const ClockGrid g(16'000'000, {2500.0, 300.0, 3});
    for (TimePs t = 0; t < 2'000'000'000; t += 7'777'777) {
        const std::int64_t n = g.last_at_or_before(t);
        ASSERT_GE(n, 0);
        EXPECT_LE(g.at(n), t);
        EXPECT_GT(g.at(n + 1), t);
        EXPECT_EQ(g.last_at_or_before(g.at(n)), n);
        EXPECT_EQ(g.first_at_or_after(g.at(n)), n);
        EXPECT_EQ(g.first_after(g.at(n)), n + 1);
    }
}

// Next to every edge, where the inverse takes its shortcut, against a scan of the edges themselves; on a clock whose
// jitter is as large as the constructor allows, so neighbouring edges' jitter ranges almost meet.
TEST(ClockGrid, InverseMatchesAScanNextToEveryEdge) {
    for (const ClockGrid& g : {ClockGrid(50'000'000, {-40.0, 1240.0, 11}), ClockGrid(16'000'000, {3000.0, 10.0, 5})}) {
        const TimePs reach_ps = std::llround(kJitterCutSigmas * g.jitter_rms_ps()) + 2;
        for (std::int64_t k = 1; k < 3000; ++k) {
            for (const TimePs centre : {g.at(k), cycles_to_ps(k, g.hz())}) {
                for (TimePs t = centre - reach_ps; t <= centre + reach_ps; t += std::max<TimePs>(1, reach_ps / 7)) {
                    std::int64_t scan = k - 2;
                    while (g.at(scan + 1) <= t) ++scan;
                    ASSERT_EQ(g.last_at_or_before(t), scan) << "t = " << t << " ps";
                }
            }
        }
    }
}

TEST(ClockGrid, RefusesWhatNoOscillatorDoes) {
    EXPECT_THROW(ClockGrid(0, {}), cnc::BadInput);
    EXPECT_THROW(ClockGrid(50'000'000, {200'000.0, 0.0, 1}), cnc::BadInput);
    EXPECT_THROW(ClockGrid(50'000'000, {0.0, -1.0, 1}), cnc::BadInput);
    // 50 MHz: 20 000 ps; 4 sigma must stay below 5 000 ps.
    EXPECT_THROW(ClockGrid(50'000'000, {0.0, 1250.0, 1}), cnc::BadInput);
    EXPECT_NO_THROW(ClockGrid(50'000'000, {0.0, 1249.0, 1}));
}
