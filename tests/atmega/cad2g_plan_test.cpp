// The seed 003 PC program core: OCR words (eqs. 4.73, 4.77, 5.1-5.5), commands, bytes, chords, 16-bit limit.
#include <gtest/gtest.h>

#include <cstdlib>
#include <numeric>
#include <sstream>

#include "common/bad_input.hpp"
#include "host/core/cad2g/plan.hpp"
#include "host/core/cad2g/speed.hpp"
#include "host/core/gcode.hpp"

namespace cad2g = cnc::host::cad2g;
using cnc::host::MachineModel;
using cnc::host::Program;

namespace {

constexpr double kMmPerStep = 0.00625;  // seed 003 Table 5.4: 1/32 microstep of a 0.2 mm full step

Program gcode(const std::string& text, cnc::host::FeedUnit unit = cnc::host::FeedUnit::MmPerMinute) {
    std::istringstream in(text);
    cnc::host::InterpreterOptions opt;
    opt.feed_unit = unit;
    return cnc::host::interpret(in, "t.nc", opt);
}

cad2g::Plan plan(const std::string& text, cad2g::PcOptions opt = {},
                 cnc::host::FeedUnit unit = cnc::host::FeedUnit::MmPerMinute) {
    return cad2g::plan_program(gcode(text, unit), MachineModel{}, opt);
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

}  // namespace

// Thesis eqs. 5.1-5.2: 10.45 mm/s at 1/32, N = 1024: OCR 3.67 -> 3 -> 12.20 mm/s (+1.75 mm/s).
TEST(Cad2gSpeed, ThesisExampleN1024) {
    const cad2g::Ocr o = cad2g::ocr_for_speed(10.45, kMmPerStep);
    EXPECT_NEAR(o.exact, 3.6725, 1e-4);  // the thesis prints 3.67
    EXPECT_EQ(o.integer, 3);
    EXPECT_EQ(o.value, 3);
    EXPECT_FALSE(o.too_fast || o.too_slow);
    EXPECT_EQ(cad2g::step_period_cycles(3), 8192);  // 2 x 1024 x 4: 512 us
    EXPECT_DOUBLE_EQ(cad2g::step_rate_hz(3), 1953.125);
    EXPECT_NEAR(cad2g::speed_mm_per_s(3, kMmPerStep), 12.2070, 1e-4);
    EXPECT_NEAR(cad2g::speed_mm_per_s(3, kMmPerStep) - 10.45, 1.757, 1e-3);
}

// Eqs. 5.3-5.4: with N = 1 the same speed needs a 13-bit OCR that the 8-bit register cannot hold. The thesis
// prints 4784.68 -> 4784: it left out the "- 1" of its own eq. 4.73 there (16e6 / 3344 = 4784.69).
TEST(Cad2gSpeed, ThesisExampleN1NeedsThirteenBits) {
    const cad2g::Ocr o = cad2g::ocr_for_speed(10.45, kMmPerStep, {16e6, 1});
    EXPECT_NEAR(o.exact, 4783.69, 0.01);
    EXPECT_EQ(o.integer, 4783);
    EXPECT_TRUE(o.too_slow);
    EXPECT_EQ(o.value, 255);
}

// The ranges of eq. 2.3 at 1/32, N = 1024: OCR 255 .. 0 = 0.191 .. 48.8 mm/s; outside, the word is held to the range.
TEST(Cad2gSpeed, EightBitRangeAndClamps) {
    EXPECT_NEAR(cad2g::speed_mm_per_s(255, kMmPerStep), 0.1907, 1e-4);
    EXPECT_NEAR(cad2g::speed_mm_per_s(0, kMmPerStep), 48.828, 1e-3);
    const cad2g::Ocr fast = cad2g::ocr_for_speed(60.0, kMmPerStep);
    EXPECT_TRUE(fast.too_fast);
    EXPECT_EQ(fast.value, 0);
    const cad2g::Ocr zero = cad2g::ocr_for_speed(0.0, kMmPerStep);
    EXPECT_TRUE(zero.too_slow);
    EXPECT_EQ(zero.value, 255);
}

// G01 bytes: ID, X count low/high, OCR0A, OCR2A, PORTB; only X is counted (App. A3).
TEST(Cad2gPlan, G01BytesForTheThesisSpeed) {
    const cad2g::Plan p = plan("G1 X20 F10.45\n", {}, cnc::host::FeedUnit::MmPerSecond);
    ASSERT_EQ(p.commands.size(), 2U);
    EXPECT_EQ(p.commands[1].id, cad2g::CommandId::M30);
    const cad2g::Motion& m = p.commands[0].motions.at(0);
    EXPECT_EQ(m.steps_x, 3200);
    EXPECT_EQ(m.count_x, 3200);
    EXPECT_EQ(m.ocr_x.value, 3);
    // PORTB: '1' '1' DIR_Y 0, EN_Y 1 (no Y motion), STEP_Y 0, EN_X 0, HEADER 1, DIR_X 0 (+X)
    EXPECT_EQ(m.portb, 0xD2);
    EXPECT_EQ(cad2g::command_bytes(p.commands[0]), (std::vector<std::uint8_t>{0x01, 0x80, 0x0C, 3, 255, 0xD2}));
    EXPECT_EQ(cad2g::command_bytes(p.commands[1]), (std::vector<std::uint8_t>{0x3B}));
    EXPECT_TRUE(p.warnings.empty());
}

// Eqs. 4.74-4.77 on G1 X20 Y7 F600 (10 mm/s): v_x 9.439 -> OCR 4.17 -> 4; v_y 3.304 -> OCR 13.78 -> 13. The
// rate ratio 13+1 : 4+1 = 2.8 against the commanded 20:7 = 2.857 is what moves Y off its end point.
TEST(Cad2gPlan, DiagonalSpeedsAreQuantisedSeparately) {
    const cad2g::Plan p = plan("G1 X20 Y7 F600\n");
    const cad2g::Motion& m = p.commands.at(0).motions.at(0);
    EXPECT_NEAR(m.speed_x_mm_per_s, 20.0 / std::hypot(20.0, 7.0) * 10.0, 1e-9);
    EXPECT_NEAR(m.ocr_x.exact, 4.1732, 1e-4);
    EXPECT_NEAR(m.ocr_y.exact, 13.7808, 1e-4);
    EXPECT_EQ(m.ocr_x.value, 4);
    EXPECT_EQ(m.ocr_y.value, 13);
    EXPECT_EQ(m.portb, 0xC2);  // both enabled, both positive, head on
}

// §5.4.2 note 1: dx = 0 would make OCR0A meaningless, so X's timer times |dy| steps at Y's speed, X disabled.
TEST(Cad2gPlan, DxZeroWorkaround) {
    const cad2g::Plan p = plan("G1 Y-10 F600\n");
    const cad2g::Motion& m = p.commands.at(0).motions.at(0);
    EXPECT_TRUE(m.x_timebase);
    EXPECT_EQ(m.count_x, 1600);
    EXPECT_EQ(m.ocr_x.value, m.ocr_y.value);
    EXPECT_FALSE(cad2g::enabled_x(m.portb));
    EXPECT_TRUE(cad2g::enabled_y(m.portb));
    EXPECT_EQ(m.portb & 0x20, 0x20);  // DIR_Y = 1: -Y
}

// G00: both counts and one OCR from v_max (machine.rapid_feed_mm_per_min 1200 = 20 mm/s: 1.44 -> 1), head off.
TEST(Cad2gPlan, G00SendsBothCountsAndOneOcr) {
    const cad2g::Plan p = plan("G0 X-10 Y2.5\n");
    const cad2g::Motion& m = p.commands.at(0).motions.at(0);
    EXPECT_EQ(m.ocr_x.value, 1);
    EXPECT_EQ(cad2g::command_bytes(p.commands[0]),
              (std::vector<std::uint8_t>{0x00, 0x40, 0x06, 0x90, 0x01, 1, 0xC1}));  // 1600, 400; DIR_X 1
}

// §5.5: the counters are 16 bits, 409.6 mm at 1/32; a longer move is split (default) or wrapped, never silently.
TEST(Cad2gPlan, SixteenBitLimitSplitsAndWarns) {
    const cad2g::Plan p = plan("G1 X420 F1200\n");
    ASSERT_EQ(p.commands.size(), 3U);  // two G01 of 33600 steps, M30
    EXPECT_EQ(p.commands[0].motions.at(0).count_x, 33600);
    EXPECT_EQ(p.commands[1].motions.at(0).count_x, 33600);
    ASSERT_EQ(p.warnings.size(), 1U);
    EXPECT_EQ(p.warnings[0].kind, "long_move");
    EXPECT_EQ(p.warnings[0].where, "t.nc:1");
    EXPECT_TRUE(contains(p.warnings[0].text, "G01 count 67200 exceeds the 16-bit step counter (409.6 mm"));
    EXPECT_TRUE(contains(p.warnings[0].text, "sent as 2 commands"));
}

TEST(Cad2gPlan, SixteenBitLimitWrapsWhenAsked) {
    cad2g::PcOptions opt;
    opt.long_moves = cad2g::LongMoves::Wrap;
    const cad2g::Plan p = plan("G1 X420 F1200\n", opt);
    ASSERT_EQ(p.commands.size(), 2U);
    const cad2g::Motion& m = p.commands[0].motions.at(0);
    EXPECT_TRUE(m.wrapped);
    EXPECT_EQ(m.steps_x, 67200);
    EXPECT_EQ(m.count_x, 67200 - 65536);
    ASSERT_EQ(p.warnings.size(), 1U);
    EXPECT_TRUE(contains(p.warnings[0].text, "sent modulo 65536 as 1664"));
}

// Speeds outside the 8-bit range are held and reported with the line.
TEST(Cad2gPlan, OcrOutsideEightBitsIsReported) {
    const cad2g::Plan p = plan("G1 X0.1 Y20 F600\n");  // v_x = 0.05 mm/s < 0.191 mm/s
    const cad2g::Motion& m = p.commands.at(0).motions.at(0);
    EXPECT_TRUE(m.ocr_x.too_slow);
    EXPECT_EQ(m.ocr_x.value, 255);
    ASSERT_EQ(p.warnings.size(), 1U);
    EXPECT_EQ(p.warnings[0].kind, "ocr0a_range");
    EXPECT_TRUE(
        contains(to_string(p.warnings[0]), "t.nc:1: G01: OCR0A outside 0..255 in 1 of 1 commands (1 held to 255"));
}

// App. A4: chords of at most arc_step_deg with 8-bit counts, then a record with both EN bits high.
TEST(Cad2gPlan, CircleAsChords) {
    const cad2g::Plan p = plan("G0 X20 Y10\nG2 X20 Y10 I-10 J0 F600\n");
    ASSERT_EQ(p.commands.size(), 3U);
    const cad2g::Command& arc = p.commands[1];
    EXPECT_EQ(arc.id, cad2g::CommandId::G02);
    EXPECT_EQ(arc.motions.size(), 180U);  // 360 deg / 2 deg
    std::int64_t sx = 0;
    std::int64_t sy = 0;
    for (std::size_t k = 0; k < arc.motions.size(); ++k) {
        const cad2g::Motion& m = arc.motions[k];
        EXPECT_LE(std::llabs(m.steps_x), 255);
        EXPECT_LE(std::llabs(m.steps_y), 255);
        EXPECT_EQ(m.count_x, m.x_timebase ? std::llabs(m.steps_y) : std::llabs(m.steps_x));
        EXPECT_EQ((m.portb & 0x20) != 0, m.steps_y < 0);
        if (m.x_timebase) {
            // X disabled: DIR_X flips against the chord before, so the reload shows on a pin
            EXPECT_FALSE(cad2g::enabled_x(m.portb));
            ASSERT_GT(k, 0U);
            EXPECT_NE(m.portb & 0x01, arc.motions[k - 1].portb & 0x01);
        } else {
            EXPECT_EQ((m.portb & 0x01) != 0, m.steps_x < 0);
        }
        sx += m.steps_x;
        sy += m.steps_y;
    }
    EXPECT_EQ(sx, 0);  // a full circle returns to its start
    EXPECT_EQ(sy, 0);
    const std::vector<std::uint8_t> bytes = cad2g::command_bytes(arc);
    ASSERT_EQ(bytes.size(), 1U + 4U * 180U + 4U);
    EXPECT_EQ(std::vector<std::uint8_t>(bytes.end() - 4, bytes.end()),
              (std::vector<std::uint8_t>{0x00, 0xFF, 0xFF, 0xD6}));  // EN_X, EN_Y high, head on
}

// A chord through the rightmost point of a circle has dx = 0: the seed's workaround, and DIR_X flipped.
TEST(Cad2gPlan, ArcChordWithDxZeroTimesYAndFlipsDirX) {
    const cad2g::Plan p =
        plan("G0 X9.961946981 Y-0.871557427\nG3 X9.961946981 Y0.871557427 I-9.961946981 J0.871557427 F600\n");
    const cad2g::Command& arc = p.commands.at(1);
    ASSERT_EQ(arc.motions.size(), 5U);          // -5..5 deg in 2-degree chords
    const cad2g::Motion& mid = arc.motions[2];  // -1..1 deg
    EXPECT_EQ(mid.steps_x, 0);
    EXPECT_TRUE(mid.x_timebase);
    EXPECT_EQ(mid.count_x, mid.steps_y);
    EXPECT_EQ(mid.ocr_x.value, mid.ocr_y.value);
    EXPECT_EQ(arc.motions[1].portb & 0x01, 0x00);  // -3..-1 deg: +X
    EXPECT_EQ(mid.portb & 0x01, 0x01);             // flipped
    EXPECT_EQ(arc.motions[3].portb & 0x01, 0x01);  // 1..3 deg: -X
}

// Long chords are cut further so that DXL fits 8 bits: R 100 mm at 2 deg would be 558 steps.
TEST(Cad2gPlan, ChordsFitTheEightBitCount) {
    const cad2g::Plan p = plan("G0 X100\nG3 X-100 Y0 I-100 J0 F600\n");
    const cad2g::Command& arc = p.commands.at(1);
    EXPECT_EQ(arc.motions.size(), 198U);  // ceil(pi x 100 mm x 160 / 254), more than 180 deg / 2 deg
    for (const cad2g::Motion& m : arc.motions) {
        ASSERT_LE(std::llabs(m.steps_x), 255);
        ASSERT_LE(std::llabs(m.steps_y), 255);
    }
}

// The bytes go out per transfer (a command, or an arc's ID with its first chord, each chord, the terminator),
// and together they are the command bytes in order.
TEST(Cad2gPlan, TransfersConcatenateToTheCommandBytes) {
    const cad2g::Plan p = plan("G0 X20 Y10\nG1 X25 F600\nG3 X15 Y10 I-5 J0 F600\n");
    const std::vector<cad2g::Transfer> t = cad2g::transfers(p);
    std::vector<std::uint8_t> all;
    for (const cad2g::Transfer& x : t) all.insert(all.end(), x.bytes.begin(), x.bytes.end());
    std::vector<std::uint8_t> expected;
    for (const cad2g::Command& c : p.commands) {
        const auto b = cad2g::command_bytes(c);
        expected.insert(expected.end(), b.begin(), b.end());
    }
    EXPECT_EQ(all, expected);
    EXPECT_EQ(t.at(0).bytes.size(), 7U);  // G00
    EXPECT_EQ(t.at(1).bytes.size(), 6U);  // G01
    EXPECT_EQ(t.at(2).bytes.size(), 5U);  // G03 ID + first chord
    EXPECT_EQ(t.at(3).bytes.size(), 4U);
    EXPECT_EQ(t.back().bytes, (std::vector<std::uint8_t>{0x3B}));
    const auto segs = cad2g::motion_segments(p, MachineModel{});
    EXPECT_EQ(segs.size(), 2U + p.commands.at(2).motions.size());
    EXPECT_EQ(segs.at(1).steps_x, 800);
}

// Positions beyond 2^30 - 1 microsteps (machine.hpp) are refused with their line, for a caller that did not run the
// job checks first (run/job_limits.hpp): before, 2.9e13 mm was split into 7e10 commands (std::bad_alloc), and the
// step differences and the chord count of an arc of 10^24 mm overflowed int64 (UBSan).
TEST(Cad2gPlan, PositionsBeyondTheCountersAreRefusedNotOverflowed) {
    const auto message = [](const std::string& text) {
        try {
            (void)plan(text);
        } catch (const cnc::BadInput& e) {
            return std::string(e.what());
        }
        return std::string("no BadInput");
    };
    const std::string rapid = message("G91 G0 X28888888888885\n");
    EXPECT_TRUE(contains(rapid, "t.nc:1: position (2.888888889e+13, 0) mm is beyond the 1073741823 steps")) << rapid;
    const std::string arc = message("G1 X10 F600\nG2 X10 Y0 I1000000000000000000000000 J0\n");  // a full circle
    EXPECT_TRUE(contains(arc, "t.nc:2: arc of 6.28319e+24 mm needs")) << arc;
    // At the bound (2^30 - 1 steps = 6710886.39375 mm at 160 steps/mm) a move is planned, in 16-bit pieces.
    EXPECT_NO_THROW((void)plan("G0 X6710886.39375\n", cad2g::PcOptions{}));
}
