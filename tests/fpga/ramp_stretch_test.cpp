// The closed-form gains of a stretch of ramp clocks (fpga/core/ramp_stretch.hpp) against the truncated increments
// summed one clock at a time.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "fpga/core/ramp_stretch.hpp"

namespace cnc::fpga {
namespace {

struct Sums {
    RampWide velocity = 0;
    RampWide phase = 0;
};

// The increments of clocks 0 .. n-1, and what they add to the phase over clocks 0 .. n: clock i runs at the
// velocity the increments before it left.
Sums summed(const RampStretch& s, std::int64_t n) {
    Sums out;
    for (std::int64_t i = 0; i < n; ++i) {
        const std::uint64_t accel = s.accel + static_cast<std::uint64_t>(s.jerk * i);
        const auto increment = static_cast<RampWide>(accel >> 32);
        out.velocity += s.slowing ? -increment : increment;
        out.phase += out.velocity;
    }
    return out;
}

std::int64_t low_bits(RampWide v) {
    return static_cast<std::int64_t>(v);
}
std::int64_t high_bits(RampWide v) {
    return static_cast<std::int64_t>(v >> 64);
}

TEST(RampStretch, GainsAreTheTruncatedIncrementsSummedClockByClock) {
    constexpr std::uint64_t kLargest = 0xFFFF'FFFF;
    const std::vector<RampStretch> stretches = {
        {0, 0, false, 0},                // the cruise
        {kLargest << 32, 0, false, 0},   // the largest acceleration register, held
        {kLargest << 32, 0, true, 0},    // and taken off
        {kLargest, kLargest, false, 0},  // the largest jerk from its first clock: increments 0, 1, 2, ...
        {kLargest * 400, -std::int64_t{kLargest}, true, 0},  // falling to increments of 0 at the end, slowing
        {0x1234'5678'9ABC, 0x12345, false, 0},               // a jerk of a fraction of a unit a clock
        {0x1234'5678'9ABC, -0x12345, false, 0},
        {(kLargest << 32) - 3 * 0x12345, 0x12345, true, 0},  // past the largest the acceleration register gives
    };
    for (const RampStretch& s : stretches) {
        for (std::int64_t n : {0, 1, 2, 3, 7, 64, 399, 400, 100'000}) {
            SCOPED_TRACE(testing::Message()
                         << "accel " << s.accel << " jerk " << s.jerk << " slowing " << s.slowing << " clocks " << n);
            if (s.jerk < 0 && static_cast<std::uint64_t>(-s.jerk) * static_cast<std::uint64_t>(n) > s.accel) continue;
            if (s.jerk > 0 && s.accel + static_cast<std::uint64_t>(s.jerk * n) < s.accel) continue;
            const Sums expected = summed(s, n);
            const RampGain got = stretch_gain(s, n);
            EXPECT_EQ(low_bits(got.velocity), low_bits(expected.velocity));
            EXPECT_EQ(high_bits(got.velocity), high_bits(expected.velocity));
            EXPECT_EQ(low_bits(got.phase), low_bits(expected.phase));
            EXPECT_EQ(high_bits(got.phase), high_bits(expected.phase));
        }
    }
}

}  // namespace
}  // namespace cnc::fpga
