// Laser exposure per mm of path against hand-computed dwell times.
#include <gtest/gtest.h>

#include <vector>

#include "metrics/laser_exposure.hpp"

using namespace cnc;

namespace {

// The tool along X at 10 mm/s, a sample every 12.5 ms (0.125 mm: bins of 0.5 mm close exactly), with a
// 0.5 s stop at 5 mm; the laser on throughout.
std::vector<ToolSample> run_with_dwell() {
    std::vector<ToolSample> tool;
    TimePs t = 0;
    double x = 0.0;
    const TimePs step_ps = 12'500 * kPsPerUs;
    tool.push_back({t, {x, 0.0}});
    for (int i = 1; i <= 160; ++i) {
        t += step_ps;
        x += 0.125;
        tool.push_back({t, {x, 0.0}});
        if (i == 40) {  // at 5 mm: stand still for 0.5 s
            t += 500 * kPsPerMs;
            tool.push_back({t, {x, 0.0}});
        }
    }
    return tool;
}

}  // namespace

TEST(LaserExposure, ConstantFeedGivesItsInverseAndADwellShowsAsPeak) {
    const EdgeLog laser{"laser", true, {}};
    const metrics::LaserExposure e = metrics::laser_exposure(run_with_dwell(), laser);
    // 20 mm in 2 s of motion plus 0.5 s standing: 2.5 s over 20 mm = 0.125 s/mm.
    EXPECT_DOUBLE_EQ(e.lasered_path_mm, 20.0);
    EXPECT_NEAR(e.on_time_s, 2.5, 1e-12);
    EXPECT_NEAR(e.mean_s_per_mm, 0.125, 1e-12);
    // The bin [5, 5.5) mm holds the stop and 0.05 s of motion: 0.55 s / 0.5 mm = 1.1 s/mm; elsewhere 60 / F
    // at F600 = 0.1 s/mm.
    EXPECT_NEAR(e.peak_s_per_mm, 1.1, 1e-9);
    EXPECT_DOUBLE_EQ(e.peak_at_path_mm, 5.0);
}

TEST(LaserExposure, OnlyTheLaseredPathCounts) {
    // Laser on from 1 s to 1.5 s only: 5 mm of path (5 .. 10 mm, right after the 0.5 s stop), 0.5 s: 0.1 s/mm.
    const EdgeLog laser{"laser", false, {{1'000 * kPsPerMs, true}, {1'500 * kPsPerMs, false}}};
    const metrics::LaserExposure e = metrics::laser_exposure(run_with_dwell(), laser);
    EXPECT_NEAR(e.lasered_path_mm, 5.0, 1e-9);
    EXPECT_NEAR(e.on_time_s, 0.5, 1e-12);
    EXPECT_NEAR(e.mean_s_per_mm, 0.1, 1e-9);
    EXPECT_NEAR(e.peak_s_per_mm, 0.1, 1e-9);
}
