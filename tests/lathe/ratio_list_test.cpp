// The firmware's B(n) list for the pitches of seed 002 (the threads of §4.4, the feeds of §2.5.3), against
// numbers worked out from the thesis's formulas (it prints no table of lists).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "lathe/core/ratio_list.hpp"

namespace {

using cnc::lathe::make_ratio_list;
using cnc::lathe::MakelistMode;

int sum(const std::vector<std::uint8_t>& b) {
    return std::accumulate(b.begin(), b.end(), 0);
}

// Worked out: 0.04 mm -> 14/57, lambda error -5.5e-5 (14/57 - 156/635 = -5.53e-5), pitch 0.039991 mm.
TEST(RatioList, FineFeedIs14Over57) {
    const auto l = make_ratio_list(4, MakelistMode::Intended);
    EXPECT_EQ(l.num, 14);
    EXPECT_EQ(l.den, 57);
    EXPECT_EQ(l.b.size(), 57u);
    EXPECT_EQ(sum(l.b), 14);
    EXPECT_NEAR(l.lambda_error, 14.0 / 57.0 - 156.0 / 635.0, 1e-12);
    EXPECT_NEAR(l.lambda_error, -5.5e-5, 0.05e-5);
    EXPECT_NEAR(l.pitch_produced_mm, 0.039991, 0.0000005);
}

// Worked out: 0.08 mm -> 57/116, lambda error +4.1e-5, pitch 0.080007 mm.
TEST(RatioList, CoarseFeedIs57Over116) {
    const auto l = make_ratio_list(8, MakelistMode::Intended);
    EXPECT_EQ(l.num, 57);
    EXPECT_EQ(l.den, 116);
    EXPECT_EQ(sum(l.b), 57);
    EXPECT_NEAR(l.lambda_error, 57.0 / 116.0 - 312.0 / 635.0, 1e-12);
    EXPECT_NEAR(l.pitch_produced_mm, 0.080007, 0.0000005);
}

// With the constants of §2.5.3, 1.0 mm is exactly 780/127: seven 6s then 7, then 17 groups of (six 6s, 7); eighteen 7s,
// sum 780.
TEST(RatioList, M6PitchIsExactWithTheSeedPattern) {
    const auto l = make_ratio_list(100, MakelistMode::Intended);
    EXPECT_EQ(l.num, 780);
    EXPECT_EQ(l.den, 127);
    std::vector<std::uint8_t> expected(7, 6);
    expected.push_back(7);
    for (int g = 0; g < 17; ++g) {
        expected.insert(expected.end(), 6, 6);
        expected.push_back(7);
    }
    ASSERT_EQ(expected.size(), 127u);
    EXPECT_EQ(l.b, expected);
    EXPECT_EQ(std::count(l.b.begin(), l.b.end(), 7), 18);
    EXPECT_EQ(sum(l.b), 780);
    EXPECT_EQ(l.lambda_error, 0.0);
}

// With the constants of §2.5.3, every multiple of 0.05 mm is k/127 exactly (lambda = 39 P / 635 = 780 P / 12700);
// 1.5 mm starts 9,9,9,9,10.
TEST(RatioList, MultiplesOfFiveHundredthsAreExactOver127) {
    for (const int p : {50, 70, 80, 100, 125, 150, 175, 200, 250, 300}) {
        const auto l = make_ratio_list(p, MakelistMode::Intended);
        SCOPED_TRACE(p);
        EXPECT_EQ(l.den, 127);
        EXPECT_EQ(l.num, 780 * p / 100);
        EXPECT_EQ(sum(l.b), l.num);
        EXPECT_EQ(l.lambda_error, 0.0);
    }
    const auto l = make_ratio_list(150, MakelistMode::Intended);
    EXPECT_EQ((std::vector<std::uint8_t>(l.b.begin(), l.b.begin() + 5)), (std::vector<std::uint8_t>{9, 9, 9, 9, 10}));
}

// The rounding bound of §2.2: |lambda error| < 1 / (2 d) for the chosen d <= 150, for every 2-decimal pitch up to
// the uint8 limit; and the list takes only the values floor(lambda) and floor(lambda) + 1.
TEST(RatioList, RoundingBoundHoldsForEveryPitch) {
    for (int p = 1; p <= cnc::lathe::kMaxPitchCentiMm; ++p) {
        const auto l = make_ratio_list(p, MakelistMode::Intended);
        ASSERT_LE(l.den, 150);
        ASSERT_LT(std::abs(l.lambda_error), 0.5 / l.den) << p;
        const auto [lo, hi] = std::minmax_element(l.b.begin(), l.b.end());
        ASSERT_LE(*hi - *lo, 1) << p;
    }
}

// 4151 is the largest pitch whose entries fit the uint8 info: 39 * 4151 / 635 = 254.95 (entries 254, 255),
// 39 * 4152 / 635 = 255.007 (an entry of 256 would wrap to 0).
TEST(RatioList, Uint8LimitIs41Point51Mm) {
    EXPECT_EQ(cnc::lathe::kMaxPitchCentiMm, 4151);
    const auto l = make_ratio_list(4151, MakelistMode::Intended);
    EXPECT_EQ(*std::max_element(l.b.begin(), l.b.end()), 255);
    EXPECT_LT(39.0 * 4151 / 635, 255.0);
    EXPECT_GT(39.0 * 4152 / 635, 255.0);
}

// The listing as §2.5.3 prints it (int32 against uint32) gives 46635/34 for 1.00 mm (our emulation of it).
TEST(RatioList, AsPrintedReproducesTheSeedsDefect) {
    const auto l = make_ratio_list(100, MakelistMode::AsPrinted);
    EXPECT_EQ(l.num, 46635);
    EXPECT_EQ(l.den, 34);
    EXPECT_EQ(l.b.size(), 34u);
}

}  // namespace
