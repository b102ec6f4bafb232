// Whole atmega runs of seed 003 §5.6's proposals (avr.variant): the rate each axis gets from its compare word,
// worked from f / (2 N (OCR + 1)) here (seed 003 eq. 2.3, f = 16 MHz, 160 steps/mm), against the STEP edges the
// firmware makes on the simulated ATmega328P.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "atmega_test_util.hpp"

using cnc::TimePs;
using cnc::test::kAvrCyclePs;
using cnc::test::periods;
using cnc::test::run_atmega;

namespace {

constexpr double kF_hz = 16e6;                      // seed 003 §5.2.4
constexpr double kStepsPerMm = 160.0;               // 1/32 microstep on the GT2 20T belt (seed 003 Table 5.4)
constexpr double kCommanded = 10.45 * kStepsPerMm;  // eqs. 5.1-5.2: 1672 steps/s

// OCR = f / (2 N v) - 1 rounded to the nearest integer (seed 003 §5.6 improvements 1 and 3), v in steps/s.
int rounded_ocr(double prescaler, double steps_per_s) {
    return static_cast<int>(std::floor(kF_hz / (2.0 * prescaler * steps_per_s) - 1.0 + 0.5));
}

double rate_hz(double prescaler, int ocr) {
    return kF_hz / (2.0 * prescaler * (ocr + 1));
}

double error_pct(double achieved, double commanded) {
    return (achieved / commanded - 1.0) * 100.0;
}

// The Y move at 10.45 mm/s (tests/atmega/data/speed_10_45_y.nc) on the speed_10_45 scenario.
const std::string kYJob = "scenario.job=" + std::string(CNC_SOURCE_DIR) + "/tests/atmega/data/speed_10_45_y.nc";

}  // namespace

// 10.45 mm/s on X: OCR0A 3.67 rounds to 4, 1562.5 steps/s, -6.55 % (the seed truncates to 3: +16.81 %).
TEST(AtmegaVariant, RoundedXRateIsTheRoundedCompareValue) {
    const int ocr = rounded_ocr(1024, kCommanded);
    ASSERT_EQ(ocr, 4);
    const double expected_pct = error_pct(rate_hz(1024, ocr), kCommanded);
    EXPECT_NEAR(expected_pct, -6.55, 0.005);

    const auto out = run_atmega("speed_10_45", {"avr.variant=rounded", "trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    EXPECT_EQ(out.report.at("atmega").at("variant"), "rounded");
    EXPECT_EQ(out.report.at("atmega").at("commands").at(0).at("motions").at(0).at("ocr").at(0), ocr);
    const auto& x = out.metrics.axes.at(0);
    ASSERT_EQ(x.rising_edges, 3200U);
    ASSERT_EQ(x.runs.size(), 1U);
    EXPECT_DOUBLE_EQ(*x.runs[0].rate_achieved_steps_per_s, rate_hz(1024, ocr));
    EXPECT_NEAR(*x.runs[0].rate_error_pct, expected_pct, 1e-9);
    EXPECT_NEAR(*out.metrics.moves.at(0).timing.feed_error_pct, expected_pct, 0.01);
}

// The same speed on Y alone: "rounded" times it on X's Timer0 (seed 003 §5.4.2 note 1), so Y gets OCR 4's
// -6.55 % too.
TEST(AtmegaVariant, RoundedYAloneRunsOnXsTimebase) {
    const auto out = run_atmega("speed_10_45", {"avr.variant=rounded", kYJob});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& y = out.metrics.axes.at(1);
    ASSERT_EQ(y.rising_edges, 3200U);
    ASSERT_EQ(y.runs.size(), 1U);
    EXPECT_NEAR(*y.runs[0].rate_error_pct, error_pct(rate_hz(1024, 4), kCommanded), 1e-9);
}

// timer1-y: Y on Timer1 at N = 1, OCR1A = 16e6 / (2 x 1672) - 1 = 4783.69 -> 4784. OC1A (PB1, STEP_Y) toggles every
// 4785 cycles, a STEP period of 2 x 4785 cycles: 1671.891 steps/s, -0.0065 %, counted to 3200 on Timer1's own flag.
TEST(AtmegaVariant, TimerOneYRateIsWithinATenthOfAPercent) {
    const int ocr = rounded_ocr(1, kCommanded);
    ASSERT_EQ(ocr, 4784);
    const double expected_pct = error_pct(rate_hz(1, ocr), kCommanded);
    EXPECT_NEAR(expected_pct, -0.0065, 0.0001);

    const auto out = run_atmega("speed_10_45", {"avr.variant=timer1-y", kYJob, "trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    EXPECT_EQ(out.report.at("atmega").at("commands").at(0).at("motions").at(0).at("ocr").at(1), ocr);
    const auto yr = out.arch.input.axes[1].step.rising();
    ASSERT_EQ(yr.size(), 3200U);
    for (const TimePs d : periods(yr)) ASSERT_EQ(d, 2 * (ocr + 1) * kAvrCyclePs);
    EXPECT_TRUE(out.arch.input.axes[0].step.rising().empty());
    const auto& y = out.metrics.axes.at(1);
    ASSERT_EQ(y.runs.size(), 1U);
    EXPECT_NEAR(*y.runs[0].rate_error_pct, expected_pct, 1e-9);
    EXPECT_LT(std::fabs(*y.runs[0].rate_error_pct), 0.1);
    EXPECT_NEAR(*out.metrics.moves.at(0).timing.feed_error_pct, expected_pct, 0.01);
}

// timer1-y on G1 X20 Y7 at 10 mm/s (§5.6 improvement 2): OCR0A = 16e6 / (2048 x 1510.2) - 1 = 4.17 -> 4, X at
// 1562.5 steps/s; Y asked 7/20 of it, 546.875 steps/s: OCR1A = 16e6 / (2 x 546.875) - 1 = 14627.6 -> 14628. Both
// axes then run the same +3.46 % over the commanded split, and in the 2 x 1024 x 5 x 3200 cycles X counts, Y rises
// at 14629 (2j - 1) cycles: j = 1..floor((2 x 1024 x 5 x 3200 / 14629 + 1) / 2) = 1120 = 7 mm (the seed: 1143).
TEST(AtmegaVariant, TimerOneYDiagonalHoldsTheRatio) {
    const double dz = std::sqrt(20.0 * 20.0 + 7.0 * 7.0);
    const double commanded_x = 10.0 * 20.0 / dz * kStepsPerMm;
    const double commanded_y = 10.0 * 7.0 / dz * kStepsPerMm;
    const int ocr_x = rounded_ocr(1024, commanded_x);
    const int ocr_y = rounded_ocr(1, 7.0 / 20.0 * rate_hz(1024, ocr_x));
    ASSERT_EQ(ocr_x, 4);
    ASSERT_EQ(ocr_y, 14628);
    const std::int64_t x_cycles = 2 * 1024 * (ocr_x + 1) * 3200;
    const std::int64_t y_steps = (x_cycles / (ocr_y + 1) + 1) / 2;
    ASSERT_EQ(y_steps, 1120);

    const auto out = run_atmega("diagonal_20x7", {"avr.variant=timer1-y", "mechanics.model=ideal"});
    ASSERT_TRUE(out.ok) << out.failure;
    EXPECT_EQ(out.arch.input.axes[0].step.rising().size(), 3200U);
    EXPECT_EQ(out.arch.input.axes[1].step.rising().size(), static_cast<std::size_t>(y_steps));
    const auto& x = out.metrics.axes.at(0);
    const auto& y = out.metrics.axes.at(1);
    ASSERT_EQ(x.runs.size(), 1U);
    ASSERT_EQ(y.runs.size(), 1U);
    EXPECT_NEAR(*x.runs[0].rate_error_pct, error_pct(rate_hz(1024, ocr_x), commanded_x), 1e-9);
    EXPECT_NEAR(*y.runs[0].rate_error_pct, error_pct(rate_hz(1, ocr_y), commanded_y), 1e-9);
    EXPECT_NEAR(*x.runs[0].rate_error_pct, *y.runs[0].rate_error_pct, 0.01);
}
