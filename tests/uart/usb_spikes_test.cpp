// USB latency spikes: the rate and the exponential mean as asked (bounds computed here), reproducible, directions
// apart.
#include <gtest/gtest.h>

#include <cmath>

#include "uart/core/usb_spikes.hpp"

using namespace cnc;
using namespace cnc::uart;

namespace {
constexpr UsbSpikeRates kRates{0.01, 20 * kPsPerMs};
constexpr int kFrames = 400'000;
}  // namespace

TEST(UsbSpikes, NoneWithoutARate) {
    const UsbSpikeDraw draw(UsbSpikeRates{}, 1, 1);
    for (std::int64_t n = 0; n < 10'000; ++n) EXPECT_EQ(draw.extra_ps(n), 0);
}

// The count of spikes is binomial(n, rate): within 5 standard deviations. An exponential's standard deviation is its
// mean, so the mean of k spikes is within 5 mean / sqrt(k) of it; and its median is mean ln 2.
TEST(UsbSpikes, RateAndMeanAsAsked) {
    const UsbSpikeDraw draw(kRates, 7, 1);
    double count = 0;
    double sum_ps = 0;
    double below_median = 0;
    const double mean = static_cast<double>(kRates.mean_ps);
    for (std::int64_t n = 0; n < kFrames; ++n) {
        const TimePs e = draw.extra_ps(n);
        if (e == 0) continue;
        ++count;
        sum_ps += static_cast<double>(e);
        below_median += static_cast<double>(e) < mean * std::log(2.0) ? 1.0 : 0.0;
    }
    const double expected = kFrames * kRates.rate;
    EXPECT_NEAR(count, expected, 5.0 * std::sqrt(expected * (1.0 - kRates.rate)));
    EXPECT_NEAR(sum_ps / count, mean, 5.0 * mean / std::sqrt(count));
    EXPECT_NEAR(below_median / count, 0.5, 5.0 * 0.5 / std::sqrt(count));
}

TEST(UsbSpikes, TheSameSeedTheSameSpikesAndTheDirectionsApart) {
    const UsbSpikeDraw a(kRates, 3, 0);
    const UsbSpikeDraw again(kRates, 3, 0);
    const UsbSpikeDraw other(kRates, 3, 1);
    int same_as_other = 0;
    int spikes = 0;
    for (std::int64_t n = 0; n < 100'000; ++n) {
        EXPECT_EQ(a.extra_ps(n), again.extra_ps(n));
        if (a.extra_ps(n) > 0) {
            ++spikes;
            same_as_other += other.extra_ps(n) > 0 ? 1 : 0;
        }
    }
    EXPECT_GT(spikes, 0);
    EXPECT_LT(same_as_other, spikes / 10);  // independent: about rate x spikes coincide
}
