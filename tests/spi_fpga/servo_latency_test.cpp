// Servo wake-up latency model (models/host/servo/core/latency.hpp): the PRNG, the inverse CDFs and the bounds.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "host/servo/core/latency.hpp"

using cnc::kPsPerNs;
using cnc::kPsPerUs;
using cnc::TimePs;
using namespace cnc::host::servo;

// splitmix64's reference outputs for seed 0 (S. Vigna's splitmix64.c; recomputed independently in Python).
TEST(SplitMix64, ReferenceSequence) {
    SplitMix64 rng(0);
    EXPECT_EQ(rng.next(), 0xE220'A839'7B1D'CDAFULL);
    EXPECT_EQ(rng.next(), 0x6E78'9E6A'A1B9'65F4ULL);
}

TEST(LatencyQuantile, UniformIsLinearInU) {
    const LatencyConfig cfg{LatencyDistribution::Uniform, 50 * kPsPerUs};
    EXPECT_EQ(latency_quantile(cfg, 0.0), 0);
    EXPECT_EQ(latency_quantile(cfg, 0.5), 25 * kPsPerUs);
    EXPECT_EQ(latency_quantile(cfg, 0.25), 12'500 * kPsPerNs);
}

TEST(LatencyQuantile, TruncatedExponentialOfScaleMaxOverFive) {
    const LatencyConfig cfg{LatencyDistribution::Exponential, 50 * kPsPerUs};
    EXPECT_EQ(latency_quantile(cfg, 0.0), 0);
    // -10 us * ln(1 - 0.5 (1 - e^-5)) = 6.8643 us, whole ns
    EXPECT_EQ(latency_quantile(cfg, 0.5), 6'864 * kPsPerNs);
    // u -> 1 reaches the bound and never passes it
    EXPECT_EQ(latency_quantile(cfg, 1.0 - 0x1.0p-53), 50 * kPsPerUs);
}

TEST(LatencyQuantile, ZeroBoundMeansExactWakeups) {
    for (const LatencyDistribution d : {LatencyDistribution::Exponential, LatencyDistribution::Uniform}) {
        LatencyGenerator g({d, 0}, 7);
        for (int i = 0; i < 100; ++i) ASSERT_EQ(g.next(), 0);
    }
}

TEST(LatencyGenerator, BoundedWholeNanosecondsWithTheExpectedShape) {
    LatencyGenerator g({LatencyDistribution::Exponential, 50 * kPsPerUs}, 1);
    const int n = 100'000;
    long double sum = 0;
    int above_80pct = 0;
    for (int i = 0; i < n; ++i) {
        const TimePs l = g.next();
        ASSERT_GE(l, 0);
        ASSERT_LE(l, 50 * kPsPerUs);
        ASSERT_EQ(l % kPsPerNs, 0);
        sum += l;
        above_80pct += l > 40 * kPsPerUs ? 1 : 0;
    }
    // theory: mean b - M e^(-M/b) / (1 - e^(-M/b)) = 9.661 us; P(L > 0.8 M) = 1.166 %
    EXPECT_NEAR(static_cast<double>(sum / n) / kPsPerUs, 9.661, 0.1);
    EXPECT_NEAR(100.0 * above_80pct / n, 1.166, 0.15);
}

TEST(LatencyGenerator, SameSeedSameStreamOtherSeedOtherStream) {
    const LatencyConfig cfg{LatencyDistribution::Uniform, 100 * kPsPerUs};
    LatencyGenerator a(cfg, 42);
    LatencyGenerator b(cfg, 42);
    LatencyGenerator c(cfg, 43);
    int differ = 0;
    for (int i = 0; i < 1000; ++i) {
        const TimePs la = a.next();
        ASSERT_EQ(la, b.next());
        differ += la != c.next() ? 1 : 0;
    }
    EXPECT_GT(differ, 990);
}
