// Frame layout of the spi-fpga link (models/spi/README.md): byte positions, round trips, rate conversions and
// the rate words that cannot be encoded.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/bad_input.hpp"
#include "spi/core/spi_frame.hpp"
#include "support/bad_input_message.hpp"

namespace cnc::spi {
namespace {

using Bytes = std::vector<std::uint8_t>;

using cnc::test::bad_input_message;

TEST(SpiFrame, SizesForOneToEightAxes) {
    EXPECT_EQ(frame_bytes(1), 5U);
    EXPECT_EQ(frame_bytes(2), 9U);
    EXPECT_EQ(frame_bits(2), 72U);
    EXPECT_EQ(frame_bits(8), 264U);
}

TEST(SpiFrame, CommandBytesAreHeaderThenBigEndianWordsWithDirectionInBit31) {
    const Bytes b = encode_command({{{0x0012'3456, true}, {0x3FFF'FFFF, false}}}, 101);
    EXPECT_EQ(b, (Bytes{0x52, 0x80, 0x12, 0x34, 0x56, 0x3F, 0xFF, 0xFF, 0xFF}));
    EXPECT_EQ(encode_rate_word({0, true}, 101), 0x8000'0000U);  // stopped: direction sent as given
    EXPECT_EQ(encode_rate_word({0, false}, 101), 0U);
}

TEST(SpiFrame, LaserIsBit30OfTheXWordOnly) {
    // X stopped backwards with the laser on: 0x4000'0000; Y forward at 0x0012'3456: 0x8012'3456 (bit 30 clear).
    const Bytes on = encode_command({{{0, false}, {0x0012'3456, true}}, true}, 101);
    EXPECT_EQ(on, (Bytes{0x52, 0x40, 0x00, 0x00, 0x00, 0x80, 0x12, 0x34, 0x56}));
    // Reserved bit 30 of the Y word set by hand: ignored, the period stays 0x0012'3456 and the laser off.
    const Bytes reserved{0x52, 0x00, 0x00, 0x00, 0x00, 0xC0, 0x12, 0x34, 0x56};
    const auto back = decode_command(reserved, 2);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(*back, (Command{{{0, false}, {0x0012'3456, true}}, false}));
    EXPECT_EQ(decode_rate_word(0xFFFF'FFFFU), (AxisRate{kMaxPeriodCycles, true}));
    EXPECT_THROW((void)encode_command({{}, true}, 101), std::invalid_argument);  // no X word to carry it
}

TEST(SpiFrame, CommandRoundTrip) {
    for (const bool laser : {false, true}) {
        const Command command{{{101, true}, {0, false}, {kMaxPeriodCycles, false}, {5000, true}}, laser};
        const auto back = decode_command(encode_command(command, 101), 4);
        ASSERT_TRUE(back.has_value());
        EXPECT_EQ(*back, command);
    }
}

TEST(SpiFrame, DecodeRejectsWrongLengthOrHeader) {
    Bytes b = encode_command({{{200, true}, {300, false}}}, 1);
    EXPECT_FALSE(decode_command(b, 1).has_value());  // 9 bytes for 1 axis
    EXPECT_FALSE(decode_command(Bytes(b.begin(), b.end() - 1), 2).has_value());
    b[0] = 0x00;
    EXPECT_FALSE(decode_command(b, 2).has_value());
    b[0] = kCmdRates;
    EXPECT_TRUE(decode_command(b, 2).has_value());
}

TEST(SpiFrame, FeedbackBytesAndRoundTrip) {
    Feedback f;
    f.status = {3, false, true, false};
    f.counts = {1234, -2, std::numeric_limits<std::int32_t>::min()};
    const Bytes b = encode_feedback(f);
    EXPECT_EQ(b, (Bytes{0xA3, 0x00, 0x00, 0x04, 0xD2, 0xFF, 0xFF, 0xFF, 0xFE, 0x80, 0x00, 0x00, 0x00}));
    const Feedback back = decode_feedback(b, 3);
    EXPECT_EQ(back.status, f.status);
    EXPECT_EQ(back.counts, f.counts);
    EXPECT_THROW((void)decode_feedback(b, 2), std::invalid_argument);
}

TEST(SpiFrame, StatusByteBitsAndSaturatedLevel) {
    EXPECT_EQ(encode_status({}), 0x80);
    EXPECT_EQ(encode_status({4, true, false, false}), 0x94);
    EXPECT_EQ(encode_status({0, false, false, true}), 0xC0);
    EXPECT_EQ(encode_status({99, true, true, true}), 0xFF);  // level saturates at 15
    EXPECT_EQ(decode_status(0xFF).fifo_level, 15U);
    EXPECT_EQ(decode_status(0x94), (SlaveStatus{4, true, false, false}));
}

TEST(SpiFrame, WidenCountFollowsWrapsBothWays) {
    EXPECT_EQ(widen_count(0, 5), 5);
    EXPECT_EQ(widen_count(0x7FFF'FFFFLL, std::numeric_limits<std::int32_t>::min()), 0x8000'0000LL);
    EXPECT_EQ(widen_count(0x1'0000'0005LL, 3), 0x1'0000'0003LL);
    EXPECT_EQ(widen_count(-0x1'0000'0000LL, -1), -0x1'0000'0001LL);
}

TEST(SpiFrame, PeriodForRateRoundsToNearestClock) {
    EXPECT_EQ(period_for_rate(10'000.0, 50'000'000, 101), 5'000U);
    EXPECT_EQ(period_for_rate(-10'000.0, 50'000'000, 101), 5'000U);  // magnitude only
    EXPECT_EQ(period_for_rate(3.0, 50'000'000, 101), 16'666'667U);   // 16 666 666.67
    EXPECT_EQ(period_for_rate(7.0, 50'000'000, 101), 7'142'857U);    // 7 142 857.14
    EXPECT_EQ(period_for_rate(0.0, 50'000'000, 101), 0U);
    EXPECT_EQ(period_for_rate(50'000'000.0 / 101.0, 50'000'000, 101), 101U);
    const AxisRate r = axis_rate_for(-1'600.0, 50'000'000, 101);
    EXPECT_EQ(r, (AxisRate{31'250, false}));
    EXPECT_DOUBLE_EQ(rate_for_period(31'250, 50'000'000), 1'600.0);
    EXPECT_DOUBLE_EQ(rate_for_period(0, 50'000'000), 0.0);
}

TEST(SpiFrame, RateWordOverflowIsBadInputWithTheNumbers) {
    // Too slow: 0.01 steps/s needs 5e9 clocks, the field holds 2^30 - 1 = 1,073,741,823.
    const std::string slow = bad_input_message([] { (void)period_for_rate(0.01, 50'000'000, 101, "axis x"); });
    EXPECT_NE(slow.find("axis x: "), std::string::npos) << slow;
    EXPECT_NE(slow.find("5000000000 clocks"), std::string::npos) << slow;
    EXPECT_NE(slow.find("30-bit field"), std::string::npos) << slow;
    EXPECT_NE(slow.find("1073741823"), std::string::npos) << slow;
    // 0.0466 steps/s needs 1,072,961,373.4 clocks (fits); 0.04656 needs 1,073,883,161.5 (does not).
    EXPECT_EQ(period_for_rate(0.0466, 50'000'000, 101), 1'072'961'373U);
    EXPECT_THROW((void)period_for_rate(0.04656, 50'000'000, 101), BadInput);
    // Too fast: 1 MHz needs 50 clocks < 101.
    const std::string fast = bad_input_message([] { (void)period_for_rate(1e6, 50'000'000, 101); });
    EXPECT_NE(fast.find("period of 50 clocks"), std::string::npos) << fast;
    EXPECT_NE(fast.find("101 clocks"), std::string::npos) << fast;
    EXPECT_THROW((void)period_for_rate(std::numeric_limits<double>::infinity(), 50'000'000, 101), BadInput);
    EXPECT_THROW((void)period_for_rate(std::numeric_limits<double>::quiet_NaN(), 50'000'000, 101), BadInput);
    // Just inside both ends.
    EXPECT_EQ(period_for_rate(50e6 / 1073741823.0, 50'000'000, 101), 1'073'741'823U);
    // Encoding a word directly: the period field (2^30 would overwrite the laser bit) and the minimum.
    const std::string word = bad_input_message([] {
        (void)encode_command({{{100, true}, {0x4000'0000U, true}}}, 100);
    });
    EXPECT_NE(word.find("axis 1"), std::string::npos) << word;
    EXPECT_NE(word.find("1073741824 clocks does not fit the rate word's 30-bit field"), std::string::npos) << word;
    EXPECT_THROW((void)encode_rate_word({100, true}, 101), BadInput);
}

}  // namespace
}  // namespace cnc::spi
