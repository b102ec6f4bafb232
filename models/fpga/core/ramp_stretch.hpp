// A stretch of step_gen's ramp clocks (core/step_ramp.hpp has the registers) and what its clocks add to the velocity
// and the phase, in closed form, so that the ramp finds each step's clock without running the clocks one by one.
// On the stretch's clock m the acceleration register holds accel + jerk m (2^-80 steps per clock^2), and at the
// clock's end the velocity (2^-48 steps per clock) gains or, slowing, loses it truncated to its own bits:
//   increment(m) = floor((accel + jerk m) / 2^32).
// The trapezoid holds its acceleration register, 32 bits up (jerk 0); the S-curve's jerk phases move the acceleration
// by the jerk register a clock, up or down.
#pragma once
#include <cstdint>

namespace cnc::fpga {

inline constexpr int kJerkShift = 32;  // the acceleration's fraction bits below the velocity's

__extension__ typedef __int128 RampWide;

struct RampStretch {
    std::uint64_t accel = 0;  // on the stretch's first clock, 2^-80 steps per clock^2
    std::int64_t jerk = 0;  // its change per clock, 2^-80 steps per clock^3 (accel + jerk m stays >= 0 on the stretch)
    bool slowing = false;   // the increments come off the velocity
    std::int64_t length = 0;  // clocks
};

struct RampGain {
    RampWide velocity = 0;  // the increments of clocks 0 .. n-1, signed
    RampWide phase = 0;     // what they add to the phase over clocks 0 .. n: the sum of (n - m) increment(m)
};

// The increment at the end of the stretch's clock m, signed (2^-48 steps per clock).
[[nodiscard]] std::int64_t stretch_increment(const RampStretch& s, std::int64_t m);

// The gains of the stretch's first n clocks (0 <= n <= length), exact while n^2 times the largest increment stays
// within 2^120: a ramp's increments are below 2^32, an S-curve's jerk phase is shorter than 2^40 clocks (jerk n^2
// stays within the 2^80 of its velocity gain), and the trapezoid's increments over n clocks stay within its 2^48.
[[nodiscard]] RampGain stretch_gain(const RampStretch& s, std::int64_t n);

}  // namespace cnc::fpga
