// The seed 003 firmware on the ATmega328P model, seen on its pins: cycle-exact STEP timing, the timer start,
// the chord reload of App. A4, the listed Timer2 prescaler.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "atmega_test_util.hpp"

using cnc::TimePs;
using cnc::test::kAvrCyclePs;
using cnc::test::periods;
using cnc::test::run_atmega;
using cnc::test::step_period_ps;

// A command starts from a known timer state: the start byte (OUT PORTB) enables X, 8 cycles later GTCCR = 0
// releases both prescalers held by TSM (OUT PORTB, MOV, RJMP, LDI, OUT TCCR0B, STS TCCR2B: 1 + 1 + 2 + 1 + 1 + 2),
// and the first match toggles STEP X high 1024 (OCR0A + 1) cycles after that: DIR and EN lead it by 256.5 us.
TEST(AtmegaFirmware, FirstStepComesAFixedTimeAfterTheStartByte) {
    const auto out = run_atmega("speed_10_45");
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& en_x = out.arch.lines.at("n_enbl_x");
    const auto falls = en_x.falling();
    ASSERT_EQ(falls.size(), 1U);
    const auto rising = out.arch.input.axes[0].step.rising();
    EXPECT_EQ(rising.front() - falls.front(), (8 + 1024 * 4) * kAvrCyclePs);
    // the X count ends at the 6400th match (a falling edge: the pin started low); the ISR-free G01 polling
    // loop and axes_finish raise EN_X a few cycles later, before the next match could come
    const auto& pin = out.arch.lines.at("step_x_pin");
    const auto rises = en_x.rising();
    ASSERT_EQ(rises.size(), 2U);  // firmware init, then the end of G01
    const TimePs last_fall = out.arch.input.axes[0].step.falling().back();
    EXPECT_GT(rises.back(), last_fall);
    EXPECT_LT(rises.back() - last_fall, 40 * kAvrCyclePs);
    EXPECT_EQ(pin.rising().size(), 3200U);  // the timer stopped with the count: no pulse while disabled
}

// A hardware toggle has no jitter: every period is exactly 2 N (OCR + 1) cycles, TIE 0.
TEST(AtmegaFirmware, StepPeriodsAreExactlyTwoNTimesOcrPlusOneCycles) {
    const auto out = run_atmega("speed_10_45");
    const auto rising = out.arch.input.axes[0].step.rising();
    for (const TimePs d : periods(rising)) ASSERT_EQ(d, step_period_ps(3));  // 8192 cycles = 512 us
    const auto& step = out.arch.input.axes[0].step;
    for (std::size_t i = 0; i + 1 < step.edges.size(); i += 2) {
        ASSERT_EQ(step.edges[i + 1].t_ps - step.edges[i].t_ps, step_period_ps(3) / 2);  // 50 % duty
    }
    ASSERT_TRUE(out.metrics.pulse.tie_max_ns.has_value());
    EXPECT_EQ(*out.metrics.pulse.tie_max_ns, 0.0);
    EXPECT_EQ(*out.metrics.pulse.jitter_pp_max_ns, 0.0);
    EXPECT_EQ(out.metrics.pulse.driver_violations, 0U);
}

// App. A3 as listed: Timer2 CS = 110 is /256, while the PC computed OCR2A for /1024: Y runs 4x fast.
TEST(AtmegaFirmware, ListedTimer2PrescalerRunsY4xFast) {
    const auto out = run_atmega("diagonal_20x7", {"atmega.g01_timer2_prescaler=256"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto yr = out.arch.input.axes[1].step.rising();
    for (const TimePs d : periods(yr)) ASSERT_EQ(d, 2 * 256 * 14 * kAvrCyclePs);
    EXPECT_EQ(out.arch.input.axes[0].step.rising().size(), 3200U);
    // Y runs for X's 3200 x 10240 cycles: its rises at 7 + 14 k ticks of 256 cycles, 4571 against 1120 asked
    const TimePs x_time = 3200 * step_period_ps(4);
    const TimePs y_period = 2 * 256 * 14 * kAvrCyclePs;
    EXPECT_EQ(yr.size(), static_cast<std::size_t>((x_time - y_period / 2) / y_period + 1));
    EXPECT_EQ(yr.size(), 4571U);
}

// App. A4: the next chord is loaded when the ISR has counted X to zero, without stopping or clearing Timer0. The
// CTC match that ends a chord has just cleared TCNT0, so the new OCR0A times the next match: STEP X's toggles
// run on with no gap, each chord's 2 DXL toggles 1024 (OCR0A + 1) cycles apart, also through chords whose X is
// disabled (dx = 0: X's timer times |dy|).
TEST(AtmegaFirmware, ChordReloadKeepsTheXTimerRunning) {
    const auto out = run_atmega("circle_r10", {"trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    ASSERT_EQ(out.report.at("atmega").at("chords").at("late"), 0);
    const auto& arc = out.report.at("atmega").at("commands").at(1).at("motions");
    const TimePs t_arc = static_cast<TimePs>(std::llround(arc.at(0).at("t_begin_s").get<double>() * 1e12));
    std::vector<TimePs> toggles;
    for (const auto& e : out.arch.lines.at("step_x_pin").edges) {
        if (e.t_ps >= t_arc) toggles.push_back(e.t_ps);
    }
    std::vector<TimePs> expected;
    for (const auto& m : arc) {
        const TimePs half = 1024 * (m.at("ocr").at(0).get<TimePs>() + 1) * kAvrCyclePs;
        for (int k = 0; k < 2 * m.at("count_x").get<int>(); ++k) expected.push_back(half);
    }
    expected.erase(expected.begin());  // the first toggle starts the list
    const std::vector<TimePs> got = periods(toggles);
    ASSERT_GE(got.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) ASSERT_EQ(got[i], expected[i]) << "toggle " << i;
}
