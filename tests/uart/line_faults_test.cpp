// The fault draw of a UART line: rates as asked (binomial bounds computed here), reproducible, lines apart.
#include <gtest/gtest.h>

#include <bitset>
#include <cmath>

#include "uart/core/line_faults.hpp"

using namespace cnc::uart;

namespace {

// Counts over `frames` frames of 10 bits.
struct Counts {
    double inverted_bits = 0;
    double lost_frames = 0;
};

Counts count(const LineFaultDraw& draw, int frames) {
    Counts c;
    for (int k = 0; k < frames; ++k) {
        const FrameFault f = draw.frame(static_cast<std::uint64_t>(k), 10);
        c.inverted_bits += static_cast<double>(std::bitset<32>(f.inverted_bits).count());
        c.lost_frames += f.lost ? 1.0 : 0.0;
    }
    return c;
}

// Within 5 standard deviations of a binomial(n, p) mean.
void expect_binomial(double observed, double n, double p) {
    const double mean = n * p;
    const double sd = std::sqrt(n * p * (1.0 - p));
    EXPECT_NEAR(observed, mean, 5.0 * sd) << "n " << n << ", p " << p;
}

}  // namespace

TEST(LineFaults, NoRateNoFault) {
    const LineFaultDraw draw(LineFaultRates{}, 1, 0);
    for (std::uint64_t k = 0; k < 10'000; ++k) EXPECT_FALSE(draw.frame(k, 10).hit());
}

TEST(LineFaults, BitsAreInvertedAtTheBitErrorRate) {
    for (const double ber : {1e-4, 1e-3, 0.01, 0.3}) {
        const LineFaultDraw draw(LineFaultRates{ber, 0.0}, 7, 0);
        const int frames = 200'000;
        const Counts c = count(draw, frames);
        expect_binomial(c.inverted_bits, frames * 10.0, ber);
        EXPECT_EQ(c.lost_frames, 0.0);
    }
}

TEST(LineFaults, FramesAreLostAtTheirRate) {
    const LineFaultDraw draw(LineFaultRates{0.0, 0.02}, 7, 1);
    const int frames = 100'000;
    expect_binomial(count(draw, frames).lost_frames, frames, 0.02);
}

// Each bit position is drawn alike: the start bit (0) and the stop bit (9) as often as a data bit.
TEST(LineFaults, EveryBitOfTheFrameCanBeHit) {
    const LineFaultDraw draw(LineFaultRates{0.05, 0.0}, 3, 0);
    const int frames = 100'000;
    std::array<double, 10> per_bit{};
    for (int k = 0; k < frames; ++k) {
        const std::uint32_t m = draw.frame(static_cast<std::uint64_t>(k), 10).inverted_bits;
        for (int b = 0; b < 10; ++b) per_bit[static_cast<std::size_t>(b)] += ((m >> b) & 1U) != 0 ? 1.0 : 0.0;
    }
    for (const double n : per_bit) expect_binomial(n, frames, 0.05);
}

TEST(LineFaults, TheSameSeedGivesTheSameFaultsAndLinesDrawApart) {
    const LineFaultRates rates{0.05, 0.05};
    const LineFaultDraw a(rates, 11, 0), again(rates, 11, 0), other_line(rates, 11, 1);
    const LineFaultDraw other_seed(rates, 12, 0);
    int same_line_differs = 0, other_line_differs = 0, other_seed_differs = 0;
    for (std::uint64_t k = 0; k < 1000; ++k) {
        const FrameFault f = a.frame(k, 10);
        const FrameFault g = again.frame(k, 10);
        same_line_differs += f.inverted_bits != g.inverted_bits || f.lost != g.lost;
        other_line_differs += f.inverted_bits != other_line.frame(k, 10).inverted_bits;
        other_seed_differs += f.inverted_bits != other_seed.frame(k, 10).inverted_bits;
    }
    EXPECT_EQ(same_line_differs, 0);
    EXPECT_GT(other_line_differs, 300);  // P(two draws of a frame agree) = P(both clean) + ... ~ 0.36
    EXPECT_GT(other_seed_differs, 300);
}
