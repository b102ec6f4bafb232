// Thread metrics (docs/metrics.md "Lathe") on hand-made passes at 1 mm pitch, 40 spindle pulses per revolution.
#include <gtest/gtest.h>

#include "lathe/core/thread_metrics.hpp"

namespace {

using cnc::lathe::ThreadPass;

// Pass 1 on the helix, x = j / 40 mm, j = 0..400. Pass 2 starts 12 um behind, then runs 4 um ahead at pulse 1 and
// advances 1.001 mm per revolution: x = 1.001 j / 40 + 0.004. Common length: 0 (pass 1's start) to 10 mm (pass
// 1's end; pass 2's last pulse is at 10.0140 mm). Revolutions inside it: pass 1's ten (error 0), pass 2's from
// pulse 40 to 360 (pulse 0 is outside, pulse 400 too): eight of +1 um. Mean 8 / 18 um, max 1 um.
// Phase: pass 2 - pass 1 = 0.025 j + 4 um for j = 1..399 (pulse 400 outside): max at j = 399, 13.975 um; over
// the last 40 common pulses (360..399, mean j 379.5): 13.4875 um. Fitted pitch: pass 1 1 mm, pass 2 1.001 mm (its
// pulses 1..399 lie on one line): the mean is 0.5 um long.
TEST(ThreadMetrics, PitchAndPhaseOverTheCommonLength) {
    ThreadPass a;
    ThreadPass b;
    for (int j = 0; j <= 400; ++j) {
        a.x_mm.push_back(j / 40.0);
        b.x_mm.push_back(j == 0 ? -0.012 : 1.001 * j / 40.0 + 0.004);
    }
    const auto m = cnc::lathe::thread_metrics({a, b}, 1.0, 40);
    EXPECT_DOUBLE_EQ(m.common_from_mm, 0.0);
    EXPECT_DOUBLE_EQ(m.common_to_mm, 10.0);
    EXPECT_EQ(m.revolutions, 18);
    EXPECT_NEAR(m.pitch_error_mean_um, 8.0 / 18.0, 1e-9);
    EXPECT_NEAR(m.pitch_error_max_um, 1.0, 1e-9);
    EXPECT_NEAR(m.pitch_fit_error_um, 0.5, 1e-9);
    EXPECT_NEAR(m.phase_error_max_um, 13.975, 1e-9);
    EXPECT_NEAR(m.phase_error_end_um, 13.4875, 1e-9);
    EXPECT_EQ(m.phase_error_max_pass, 1u);
    EXPECT_EQ(m.phase_error_max_pulse, 399u);
    EXPECT_NEAR(m.phase_error_max_signed_um, 13.975, 1e-9);
}

// Pass 2 runs 30 um behind pass 1 at pulse 100 only, pass 3 20 um ahead at pulse 200 only: the max is pass 2's lag,
// where it lies and with its sign.
TEST(ThreadMetrics, PhaseMaxSaysWhichPassWhereAndWhichWay) {
    ThreadPass a;
    ThreadPass b;
    ThreadPass c;
    for (int j = 0; j <= 400; ++j) {
        a.x_mm.push_back(j / 40.0);
        b.x_mm.push_back(j / 40.0 - (j == 100 ? 0.030 : 0.0));
        c.x_mm.push_back(j / 40.0 + (j == 200 ? 0.020 : 0.0));
    }
    const auto m = cnc::lathe::thread_metrics({a, b, c}, 1.0, 40);
    EXPECT_NEAR(m.phase_error_max_um, 30.0, 1e-9);
    EXPECT_NEAR(m.phase_error_max_signed_um, -30.0, 1e-9);
    EXPECT_EQ(m.phase_error_max_pass, 1u);
    EXPECT_EQ(m.phase_error_max_pulse, 100u);
}

// Every pass is measured against the first (the thread the tool must find again), not against the one before: pass
// 2 runs 10 um ahead of pass 1 and pass 3 25 um ahead, so pass 3's error is 25 um (15 um against pass 2).
TEST(ThreadMetrics, TheThirdPassIsMeasuredAgainstTheFirst) {
    ThreadPass a;
    ThreadPass b;
    ThreadPass c;
    for (int j = 0; j <= 400; ++j) {
        a.x_mm.push_back(j / 40.0);
        b.x_mm.push_back(j / 40.0 + 0.010);
        c.x_mm.push_back(j / 40.0 + 0.025);
    }
    const auto m = cnc::lathe::thread_metrics({a, b, c}, 1.0, 40);
    EXPECT_NEAR(m.phase_error_max_um, 25.0, 1e-9);
    EXPECT_NEAR(m.phase_error_max_signed_um, 25.0, 1e-9);
    EXPECT_EQ(m.phase_error_max_pass, 2u);
    EXPECT_NEAR(m.phase_error_end_um, 25.0, 1e-9);
}

TEST(ThreadMetrics, NoPassesNoFigures) {
    const auto m = cnc::lathe::thread_metrics({}, 1.0, 40);
    EXPECT_EQ(m.revolutions, 0);
    EXPECT_EQ(m.phase_error_max_um, 0.0);
}

}  // namespace
