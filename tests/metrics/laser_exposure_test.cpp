// Laser exposure per mm of path against hand-computed dwell times.
#include <gtest/gtest.h>

#include <vector>

#include "metrics/laser/laser_exposure.hpp"

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

// As the streaming metrics fold it: the samples in windows ending before the given sample indices, the laser
// edges before each window's last sample dropped after it.
metrics::LaserExposure folded_in_windows(const std::vector<ToolSample>& tool, EdgeLog laser,
                                         std::vector<std::size_t> cuts) {
    metrics::LaserExposureFold fold;
    cuts.push_back(tool.size());
    std::size_t from = 0;
    for (const std::size_t cut : cuts) {
        fold.fold(tool.begin() + static_cast<std::ptrdiff_t>(from), tool.begin() + static_cast<std::ptrdiff_t>(cut),
                  laser);
        (void)laser.take_before(tool[cut - 1].t_ps);
        from = cut;
    }
    return fold.finish();
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

TEST(LaserExposure, FoldedInWindowsEqualsTheWholeJob) {
    const std::vector<ToolSample> tool = run_with_dwell();
    // Laser on throughout, windows ending at samples 29 (3.625 mm, inside a bin), 40 and 41 (both at 5 mm: the
    // stop between them is the next window's first interval) and 99 (12.25 mm): the figures of the whole job
    // derived above.
    const metrics::LaserExposure on = folded_in_windows(tool, EdgeLog{"laser", true, {}}, {30, 41, 42, 100});
    EXPECT_DOUBLE_EQ(on.lasered_path_mm, 20.0);
    EXPECT_NEAR(on.on_time_s, 2.5, 1e-12);
    EXPECT_NEAR(on.mean_s_per_mm, 0.125, 1e-12);
    EXPECT_NEAR(on.peak_s_per_mm, 1.1, 1e-9);
    EXPECT_DOUBLE_EQ(on.peak_at_path_mm, 5.0);
    // Laser on from 1 s to 1.5 s, windows ending inside the on stretch (samples 44 at 1.0375 s and 59 at
    // 1.225 s) and at the off edge's sample (81 at 1.5 s): 5 mm in 0.5 s, as above.
    const EdgeLog laser{"laser", false, {{1'000 * kPsPerMs, true}, {1'500 * kPsPerMs, false}}};
    const metrics::LaserExposure part = folded_in_windows(tool, laser, {45, 60, 82});
    EXPECT_NEAR(part.lasered_path_mm, 5.0, 1e-9);
    EXPECT_NEAR(part.on_time_s, 0.5, 1e-12);
    EXPECT_NEAR(part.mean_s_per_mm, 0.1, 1e-9);
    EXPECT_NEAR(part.peak_s_per_mm, 0.1, 1e-9);
}
