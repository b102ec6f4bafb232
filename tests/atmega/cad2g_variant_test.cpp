// Seed 003 §5.6's proposed PC program arithmetic (avr.variant, host/core/cad2g/variant.hpp): OCR0A rounded, v_y
// from the rounded OCR0A, OCR2A rounded ("rounded"), and Y on Timer1 at N = 1 with a 16-bit OCR1A ("timer1-y").
// Every expected word and rate is worked from f / (2 N (OCR + 1)) here (seed 003 eq. 2.3), f = 16 MHz.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "host/core/cad2g/firmware_busy.hpp"
#include "host/core/cad2g/plan.hpp"
#include "host/core/gcode.hpp"

namespace cad2g = cnc::host::cad2g;

namespace {

constexpr double kF_hz = 16e6;          // seed 003 §5.2.4
constexpr double kMmPerStep = 0.00625;  // seed 003 Table 5.4: 1/32 of a 0.2 mm full step (160 steps/mm)

double rate_hz(double prescaler, double ocr) {
    return kF_hz / (2.0 * prescaler * (ocr + 1.0));
}

cad2g::Plan plan(const std::string& text, cad2g::Variant variant) {
    std::istringstream in(text);
    cad2g::PcOptions opt;
    opt.variant = variant;
    return cad2g::plan_program(cnc::host::interpret(in, "t.nc", {}), cnc::host::MachineModel{}, opt);
}

}  // namespace

// Eqs. 5.1-5.2 against §5.6 improvement 1: 10.45 mm/s is 1672 steps/s; 16e6 / (2048 x 1672) - 1 = 3.67, truncated
// to 3 (1953.125 steps/s, 12.207 mm/s, +16.81 %) or rounded to 4 (1562.5 steps/s, 9.766 mm/s, -6.55 %).
TEST(Cad2gVariant, RoundingTheThesisExample) {
    const cad2g::Ocr t = cad2g::ocr_for_speed(10.45, kMmPerStep);
    const cad2g::Ocr r = cad2g::ocr_for_speed(10.45, kMmPerStep, {}, cad2g::OcrRounding::Nearest);
    EXPECT_NEAR(r.exact, 3.6725, 1e-4);
    EXPECT_EQ(t.value, 3);
    EXPECT_EQ(r.value, 4);
    EXPECT_EQ(r.integer, 4);
    EXPECT_FALSE(r.too_fast || r.too_slow);
    EXPECT_DOUBLE_EQ(cad2g::step_rate_hz(t.value), rate_hz(1024, 3));
    EXPECT_DOUBLE_EQ(cad2g::step_rate_hz(r.value), rate_hz(1024, 4));
    EXPECT_NEAR(cad2g::speed_mm_per_s(3, kMmPerStep), 12.207, 5e-4);
    EXPECT_NEAR(cad2g::speed_mm_per_s(4, kMmPerStep), 9.766, 5e-4);
    EXPECT_NEAR((rate_hz(1024, 4) / 1672.0 - 1.0) * 100.0, -6.55, 0.005);
    // At most half an LSB off: |OCR - exact| <= 0.5 where truncation gives up to 1.
    EXPECT_LE(std::fabs(r.value - r.exact), 0.5);
}

// The ends of the range: within half an LSB above the OCR = 0 speed rounds to 0 and is not too fast; half an LSB
// below the OCR = 255 speed rounds to 256 and is held to 255.
TEST(Cad2gVariant, RoundingAtTheEndsOfTheEightBitRange) {
    const auto speed_of_exact = [](double exact) { return kF_hz * kMmPerStep / (2.0 * 1024.0 * (exact + 1.0)); };
    const cad2g::Ocr near_top = cad2g::ocr_for_speed(speed_of_exact(-0.4), kMmPerStep, {}, cad2g::OcrRounding::Nearest);
    EXPECT_EQ(near_top.value, 0);
    EXPECT_FALSE(near_top.too_fast);
    const cad2g::Ocr beyond = cad2g::ocr_for_speed(speed_of_exact(-0.6), kMmPerStep, {}, cad2g::OcrRounding::Nearest);
    EXPECT_TRUE(beyond.too_fast);
    EXPECT_EQ(beyond.value, 0);
    const cad2g::Ocr slow = cad2g::ocr_for_speed(speed_of_exact(255.6), kMmPerStep, {}, cad2g::OcrRounding::Nearest);
    EXPECT_TRUE(slow.too_slow);
    EXPECT_EQ(slow.integer, 256);
    EXPECT_EQ(slow.value, 255);
    EXPECT_FALSE(cad2g::ocr_for_speed(speed_of_exact(255.6), kMmPerStep).too_slow);  // truncated: 255
}

// Eqs. 5.3-5.4 on the 16-bit Timer1 of §5.6: 16e6 / (2 x 1672) - 1 = 4783.69 rounds to 4784, 1671.891 steps/s:
// -0.0065 %, where the 8-bit Timer0 at N = 1024 is off by -6.55 % rounded.
TEST(Cad2gVariant, TimerOneAtPrescalerOneHoldsTheThesisExample) {
    const cad2g::Ocr o = cad2g::ocr_for_speed(10.45, kMmPerStep, cad2g::kTimer1N1, cad2g::OcrRounding::Nearest);
    EXPECT_NEAR(o.exact, 4783.69, 0.01);
    EXPECT_EQ(o.value, 4784);
    EXPECT_FALSE(o.too_slow);
    const double error_pct = (cad2g::step_rate_hz(o.value, cad2g::kTimer1N1) / 1672.0 - 1.0) * 100.0;
    EXPECT_DOUBLE_EQ(cad2g::step_rate_hz(o.value, cad2g::kTimer1N1), rate_hz(1, 4784));
    EXPECT_NEAR(error_pct, -0.0065, 0.0001);
    // The slowest Timer1 rate at N = 1: 16e6 / (2 x 65536) = 122.07 steps/s, 0.763 mm/s.
    EXPECT_TRUE(cad2g::ocr_for_speed(0.7, kMmPerStep, cad2g::kTimer1N1, cad2g::OcrRounding::Nearest).too_slow);
}

// §5.6 improvement 2 on G1 X20 Y7 at F600 (10 mm/s): v_x = 10 x 20 / sqrt(449) = 9.4388 mm/s, OCR0A 4.174 -> 4,
// whose speed is 16e6 x 0.00625 / (2048 x 5) = 9.765625 mm/s; v_y = 7/20 of that = 3.41797 mm/s, 546.875 steps/s:
// OCR2A = 16e6 / (2048 x 546.875) - 1 = 13.286 -> 13. The seed asks 3.3036 mm/s of Y (OCR2A 14.78 -> 13 as well).
TEST(Cad2gVariant, RoundedYFollowsTheSpeedOfTheRoundedX) {
    const cad2g::Plan p = plan("G1 X20 Y7 F600\n", cad2g::Variant::Rounded);
    const cad2g::Motion& m = p.commands.at(0).motions.at(0);
    EXPECT_EQ(m.ocr_x.value, 4);
    const double v_x = kF_hz * kMmPerStep / (2.0 * 1024.0 * 5.0);
    EXPECT_DOUBLE_EQ(v_x, 9.765625);
    EXPECT_NEAR(m.speed_y_mm_per_s, 7.0 / 20.0 * v_x, 1e-12);
    EXPECT_NEAR(m.ocr_y.exact, kF_hz / (2.0 * 1024.0 * (7.0 / 20.0 * v_x / kMmPerStep)) - 1.0, 1e-9);
    EXPECT_NEAR(m.ocr_y.exact, 13.286, 0.001);
    EXPECT_EQ(m.ocr_y.value, 13);
    // The frame is the seed's: 01 XL XH OCR0A OCR2A PORTB.
    EXPECT_EQ(cad2g::command_bytes(p.commands[0], p.variant),
              (std::vector<std::uint8_t>{0x01, 0x80, 0x0C, 4, 13, 0xC2}));
}

// timer1-y on the same move: OCR0A 4 as above, v_y = 3.41797 mm/s on Timer1 at N = 1:
// 16e6 / (2 x 546.875) - 1 = 14627.57 -> 14628 = 0x3924, sent low byte first; HEADER is PB3 (0x08).
TEST(Cad2gVariant, TimerOneYFrameAndWord) {
    const cad2g::Plan p = plan("G1 X20 Y7 F600\n", cad2g::Variant::Timer1Y);
    const cad2g::Motion& m = p.commands.at(0).motions.at(0);
    EXPECT_EQ(m.ocr_x.value, 4);
    EXPECT_NEAR(m.ocr_y.exact, kF_hz / (2.0 * 546.875) - 1.0, 1e-6);
    EXPECT_EQ(m.ocr_y.value, 14628);
    EXPECT_EQ(m.portb, 0xC0 | 0x08);
    EXPECT_EQ(cad2g::command_bytes(p.commands[0], p.variant),
              (std::vector<std::uint8_t>{0x01, 0x80, 0x0C, 4, 0x24, 0x39, 0xC8}));
}

// timer1-y G00 X10 Y10 at the rapid feed (1200 mm/min, 20 mm/s): X's OCR0A 16e6 / (2048 x 3200) - 1 = 1.44 -> 1,
// 3906.25 steps/s; Y at that speed (both axes at one speed, as the seed's one OCR runs them): OCR1A =
// 16e6 / (2 x 3906.25) - 1 = 2047, one Timer0 period in Timer1 ticks. The frame: 00 XL XH YL YH OCR0A OCR1AL
// OCR1AH PORTB (head off).
TEST(Cad2gVariant, TimerOneYRapidSendsYItsOwnWord) {
    const cad2g::Plan p = plan("G0 X10 Y10\n", cad2g::Variant::Timer1Y);
    const cad2g::Motion& m = p.commands.at(0).motions.at(0);
    EXPECT_EQ(m.ocr_x.value, 1);
    EXPECT_EQ(m.ocr_y.value, 2047);
    EXPECT_DOUBLE_EQ(cad2g::step_rate_hz(m.ocr_y.value, p.timer_y), rate_hz(1024, 1));
    EXPECT_EQ(cad2g::command_bytes(p.commands[0], p.variant),
              (std::vector<std::uint8_t>{0x00, 0x40, 0x06, 0x40, 0x06, 1, 0xFF, 0x07, 0xC0}));
}

// dx = 0: timer1-y's G01 counts |dy| on Y's own timer (busy for |dy| periods of 2 (OCR1A + 1) cycles); an arc chord
// keeps the seed's X timebase with Y in step, OCR1A + 1 = 1024 (OCR0A + 1).
TEST(Cad2gVariant, TimerOneYZeroDx) {
    const cad2g::Plan g01 = plan("G1 Y20 F627\n", cad2g::Variant::Timer1Y);  // 10.45 mm/s
    const cad2g::Motion& m = g01.commands.at(0).motions.at(0);
    EXPECT_TRUE(m.y_counted);
    EXPECT_FALSE(m.x_timebase);
    EXPECT_EQ(m.count_x, 3200);
    EXPECT_EQ(m.ocr_y.value, 4784);
    EXPECT_DOUBLE_EQ(cad2g::motion_s(m, g01.timer_x, g01.timer_y), 3200.0 * 2.0 * 4785.0 / kF_hz);

    // A quarter circle from (10, 0) about the origin: its first chord's dx rounds to 0 at 1 degree.
    std::istringstream in("G1 X10 Y0 F600\nG3 X0 Y10 I-10 J0\n");
    cad2g::PcOptions opt;
    opt.variant = cad2g::Variant::Timer1Y;
    opt.arc_step_deg = 0.1;
    const cad2g::Plan arc = cad2g::plan_program(cnc::host::interpret(in, "t.nc", {}), cnc::host::MachineModel{}, opt);
    int timebase_chords = 0;
    for (const cad2g::Motion& c : arc.commands.at(1).motions) {
        if (!c.x_timebase) continue;
        ++timebase_chords;
        EXPECT_FALSE(c.y_counted);
        EXPECT_EQ(c.ocr_y.value + 1, 1024 * (c.ocr_x.value + 1));
    }
    EXPECT_GT(timebase_chords, 0);
    // The terminator: 00 FF FF FF PORTB (both EN bits high, HEADER on PB3).
    EXPECT_EQ(cad2g::arc_terminator(true, cad2g::Variant::Timer1Y),
              (std::vector<std::uint8_t>{0x00, 0xFF, 0xFF, 0xFF, 0xC0 | 0x14 | 0x08}));
}
