// step_gen's S-curve (fpga/core/step_ramp.hpp, fpga/core/scurve_plan.hpp): the event model's step clocks against
// the registers updated clock by clock as the headers state them, and the profile's kinematics against the
// closed-form jerk-limited (7-phase) ramp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

#include "fpga/core/scurve_plan.hpp"
#include "fpga/core/step_ramp.hpp"
#include "fpga/core/step_schedule.hpp"
#include "ramp_step.hpp"

namespace cnc::fpga {
namespace {

// seed 000's machine at 50 MHz and 160 steps/mm: 1000 mm/s^2, 100,000 mm/s^3 and a 5 mm/s start.
constexpr double kClkHz = 50e6;
constexpr double kStepsPerMm = 160;
const std::uint32_t kAccelReg =
    static_cast<std::uint32_t>(std::round(1000 * kStepsPerMm * std::ldexp(1.0, 48) / (kClkHz * kClkHz)));
const std::uint32_t kJerkReg =
    static_cast<std::uint32_t>(std::round(1e5 * kStepsPerMm * std::ldexp(1.0, 80) / (kClkHz * kClkHz * kClkHz)));
const std::uint32_t kStartReg = static_cast<std::uint32_t>(std::round(5 * kStepsPerMm * std::ldexp(1.0, 32) / kClkHz));

std::uint64_t cruise_of_mm_per_s(double v) {
    return static_cast<std::uint64_t>(std::ldexp(1.0, 48) / std::floor(kClkHz / (v * kStepsPerMm)));
}

using Step = test::RampStep;

std::vector<Step> event_steps(const RampInputs& in) {
    RampRun run(in);
    std::vector<Step> out;
    RampRun::Step s;
    while (run.next(s)) out.push_back({s.clock, s.sub});
    return out;
}

// The headers' registers, one clock at a time, with the plan's n_j and n_a; the velocity used on every clock if asked.
struct Reference {
    std::vector<Step> steps;
    std::vector<std::int64_t> velocity;
};

Reference clock_by_clock(const RampInputs& in, std::int64_t n_j, std::int64_t n_a, bool with_velocity) {
    const std::int64_t one = std::int64_t{1} << 48;
    const std::int64_t start =
        std::max<std::int64_t>(std::min<std::int64_t>(std::int64_t{in.start_reg} * 65'536, in.cruise), 1);
    const std::int64_t t = 2 * n_j + n_a;
    const auto increment = [&](std::int64_t i) {
        const std::uint64_t k = static_cast<std::uint64_t>(std::min({i + 1, n_j, t - i}));
        const std::uint64_t accel = std::uint64_t{in.jerk_reg} * k;  // 2^-80 units: up to 2^64 - 2^32
        return static_cast<std::int64_t>(accel / (std::uint64_t{1} << 32));
    };
    std::int64_t phase = one - start;
    std::int64_t v = start;
    enum { Accel, Cruise, Decel } state = t == 0 ? Cruise : Accel;
    std::int64_t i = 0;
    std::int64_t done = 0;
    std::int64_t ramp_steps = 0;
    std::int64_t error = in.abs_dom / 2;
    Reference out;
    for (std::int64_t j = 0; done < in.abs_dom; ++j) {
        if (with_velocity) out.velocity.push_back(v);
        phase += v;
        bool stepped = false;
        if (phase >= one) {
            phase -= one;
            ++done;
            stepped = true;
            error += in.abs_sub;
            const bool sub = error >= in.abs_dom;
            if (sub) error -= in.abs_dom;
            out.steps.push_back({j, sub});
        }
        if (state == Accel) {
            v += increment(i++);
            if (i == t) {
                state = Cruise;
                ramp_steps = done;
            }
        } else if (state == Cruise) {
            if (stepped && in.abs_dom - done < ramp_steps) {
                state = Decel;
                i = 0;
            }
        } else if (i < t) {
            v -= increment(i++);
        }
    }
    return out;
}

ScurvePlan plan_of(const RampInputs& in) {
    const std::uint64_t start = std::max<std::uint64_t>(std::min(std::uint64_t{in.start_reg} << 16, in.cruise), 1);
    return plan_scurve(start, in.cruise, in.accel_reg, in.jerk_reg, in.abs_dom);
}

Reference reference(const RampInputs& in, bool with_velocity = true) {
    const ScurvePlan p = plan_of(in);
    return clock_by_clock(in, p.jerk_clocks, p.top_clocks, with_velocity);
}

TEST(ScurveRun, StepsOnTheClocksTheRegistersGiveClockByClock) {
    const std::vector<RampInputs> cases = {
        {1600, 400, cruise_of_mm_per_s(50), kStartReg, kAccelReg, kJerkReg},   // all seven phases
        {6400, 6400, cruise_of_mm_per_s(80), kStartReg, kAccelReg, kJerkReg},  // the seed's target speed
        {40, 13, cruise_of_mm_per_s(80), kStartReg, kAccelReg, kJerkReg},      // never reaches the acceleration
        {400, 1, cruise_of_mm_per_s(80), kStartReg, kAccelReg, kJerkReg},      // nor the cruise
        {1, 0, cruise_of_mm_per_s(80), kStartReg, kAccelReg, kJerkReg},
        {2, 1, cruise_of_mm_per_s(80), kStartReg, kAccelReg, kJerkReg},
        {300, 299, cruise_of_mm_per_s(50), kStartReg, kAccelReg, kJerkReg * 1000},  // a few clocks of jerk
        {50, 20, cruise_of_mm_per_s(4), kStartReg, kAccelReg, kJerkReg},            // starts above the cruise
    };
    for (const RampInputs& in : cases) {
        SCOPED_TRACE(testing::Message() << "abs " << in.abs_dom << "/" << in.abs_sub << " jerk " << in.jerk_reg);
        const Reference expected = reference(in);
        ASSERT_EQ(expected.steps.size(), in.abs_dom);
        EXPECT_EQ(event_steps(in), expected.steps);
    }
}

// The fewest steps whose plan is the whole acceleration with its mirror: one step fewer and the move is too short
// for the full acceleration; with them, there is little or nothing left to cruise.
std::uint32_t shortest_full_move(RampInputs in) {
    const auto plan_for = [&](std::uint32_t steps) {
        in.abs_dom = steps;
        return plan_of(in);
    };
    const ScurvePlan full = plan_for(std::uint32_t{1} << 31);
    std::uint32_t lo = 1;
    std::uint32_t hi = std::uint32_t{1} << 31;
    while (lo < hi) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        const ScurvePlan p = plan_for(mid);
        if (p.jerk_clocks == full.jerk_clocks && p.top_clocks == full.top_clocks) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    return lo;
}

// The event model finds each step's clock from the closed form of a whole phase of the acceleration; the registers
// run clock by clock here, on the moves where a step is likeliest to land on the wrong side of a phase's edge: the
// lengths at which the plan stops being cut (each move runs the acceleration's rising and falling jerk phases and
// their mirrors in the slowing down), one, two and three steps (no ramp, or barely one), and the largest registers
// the init packet carries (32 bits each) with the fastest cruise the STEP pulse allows (a step every 2 clocks, high
// and low a clock each).
TEST(ScurveRun, ClosedFormStepsOnTheClocksOfTheRegistersAtTheBoundaries) {
    constexpr std::uint32_t kLargest = 0xFFFF'FFFF;
    const std::uint64_t fastest = kPhaseOne / 2;
    std::vector<RampInputs> cases;
    const std::vector<RampInputs> machines = {
        {0, 0, cruise_of_mm_per_s(80), kStartReg, kAccelReg, kJerkReg},
        {0, 0, cruise_of_mm_per_s(80), kStartReg, kAccelReg, kJerkReg * 20},   // jerk phases 20 times shorter
        {0, 0, cruise_of_mm_per_s(10), kStartReg, kAccelReg, kJerkReg / 100},  // a slow jerk: increments of ~1000 units
    };
    for (RampInputs in : machines) {
        const std::uint32_t full = shortest_full_move(in);
        for (std::uint32_t steps : {1U, 2U, 3U, full / 2, full - 1, full, full + 1}) {
            in.abs_dom = steps;
            in.abs_sub = steps / 3;
            cases.push_back(in);
        }
    }
    for (std::uint32_t steps : {1U, 2U, 3U, 1000U, 40'000U}) {
        cases.push_back({steps, steps, fastest, kStartReg, kLargest, kLargest});
    }
    // From the slowest start: a step every 2^32 clocks, too many clocks to run here for two steps without a ramp.
    for (std::uint32_t steps : {3U, 1000U, 40'000U})
        cases.push_back({steps, steps / 2, fastest, 1, kLargest, kLargest});
    cases.push_back({1000, 7, fastest, kLargest, kLargest, kLargest});  // the start at the cruise: no ramp
    for (const RampInputs& in : cases) {
        SCOPED_TRACE(testing::Message() << "abs " << in.abs_dom << "/" << in.abs_sub << " cruise " << in.cruise
                                        << " start " << in.start_reg << " accel " << in.accel_reg << " jerk "
                                        << in.jerk_reg);
        const Reference expected = reference(in, false);
        ASSERT_EQ(expected.steps.size(), in.abs_dom);
        EXPECT_EQ(event_steps(in), expected.steps);
    }
}

// The kinematics of the registers: the jerk, acceleration and velocity bounds, the mirror and the end speed, on a
// long move and on moves too short for the top acceleration or the cruise.
TEST(ScurveRun, KeepsTheJerkAccelerationAndVelocityAndEndsAtTheStartSpeed) {
    const std::uint64_t start = std::uint64_t{kStartReg} << 16;
    for (std::uint32_t steps : {6400U, 400U, 40U}) {
        SCOPED_TRACE(testing::Message() << steps << " steps");
        const RampInputs in{steps, 0, cruise_of_mm_per_s(80), kStartReg, kAccelReg, kJerkReg};
        const Reference r = reference(in);
        const std::vector<std::int64_t>& v = r.velocity;
        const std::int64_t jerk_per_clock = kJerkReg / (std::int64_t{1} << 32) + 1;  // truncation moves it by one
        std::int64_t peak = 0;
        for (std::size_t k = 1; k < v.size(); ++k) {
            const std::int64_t a = v[k] - v[k - 1];
            ASSERT_LE(std::llabs(a), std::int64_t{kAccelReg}) << "clock " << k;
            if (k >= 2) {
                ASSERT_LE(std::llabs(a - (v[k - 1] - v[k - 2])), jerk_per_clock) << "clock " << k;
            }
            peak = std::max(peak, v[k]);
        }
        EXPECT_LE(peak, static_cast<std::int64_t>(in.cruise));
        // The last step comes as the deceleration's increments run out, within half a step of the start speed:
        // between it and the speed of the second step.
        const std::vector<Step>& s = r.steps;
        EXPECT_GE(v.back(), static_cast<std::int64_t>(start));
        EXPECT_LE(v.back(), v[static_cast<std::size_t>(s[1].clock)]);
        // The slowing down mirrors the speeding up within half a step: each spacing from the end lies between the
        // spacing the same distance from the start and the next one.
        const std::size_t ramp = std::min<std::size_t>(s.size() / 2, 60);
        for (std::size_t k = 1; k + 1 < ramp; ++k) {
            const std::int64_t from_start = s[k].clock - s[k - 1].clock;
            const std::int64_t next_from_start = s[k + 1].clock - s[k].clock;
            const std::int64_t from_end = s[s.size() - k].clock - s[s.size() - k - 1].clock;
            EXPECT_LE(next_from_start, from_end + 1) << "spacing " << k;
            EXPECT_LE(from_end, from_start + 1) << "spacing " << k;
        }
    }
}

// A long move: first to last step in the closed-form time of the 7-phase ramp, 2 (dv / A + A / J) for the ramps
// (each covering (v0 + vc) / 2 of their time) and the rest of the N - 1 steps at vc, within a step at the start
// speed.
TEST(ScurveRun, ALongMoveTakesTheSevenPhaseTime) {
    const RampInputs in{6400, 0, cruise_of_mm_per_s(80), kStartReg, kAccelReg, kJerkReg};
    const std::vector<Step> steps = event_steps(in);
    ASSERT_EQ(steps.size(), 6400U);
    const double one = std::ldexp(1.0, 48);
    const double v0 = static_cast<double>(std::uint64_t{kStartReg} << 16) / one;  // steps per clock
    const double vc = static_cast<double>(in.cruise) / one;
    const double a = kAccelReg / one;
    const double j = kJerkReg / std::ldexp(1.0, 80);
    ASSERT_GT(vc - v0, a * a / j);  // reaches the acceleration register
    const double ramp = (vc - v0) / a + a / j;
    const double expected = 2 * ramp + (6399 - 2 * (v0 + vc) / 2 * ramp) / vc;
    EXPECT_NEAR(static_cast<double>(steps.back().clock - steps.front().clock), expected, 1 / v0);
}

TEST(ScurvePlan, IsTheLargestThatKeepsTheCruiseAndTheMove) {
    const std::uint64_t start = std::uint64_t{kStartReg} << 16;
    const std::uint64_t cruise = cruise_of_mm_per_s(80);
    const ScurvePlan full = plan_scurve(start, cruise, kAccelReg, kJerkReg, 100'000);
    // n_j: the acceleration register over the jerk's; the gain one top clock short of the cruise.
    EXPECT_EQ(full.jerk_clocks, static_cast<std::int64_t>((std::uint64_t{kAccelReg} << 32) / kJerkReg));
    const double gain = static_cast<double>(kJerkReg) * full.jerk_clocks * (full.jerk_clocks + 1 + full.top_clocks);
    const double dv = std::ldexp(static_cast<double>(cruise - start), 32);
    EXPECT_LE(gain, dv);
    EXPECT_GT(gain + static_cast<double>(kJerkReg) * full.jerk_clocks, dv);
    // A short move: shorter jerk phases, and at the top only what the jerk's clock grid leaves (2 clocks at most).
    const ScurvePlan short_move = plan_scurve(start, cruise, kAccelReg, kJerkReg, 40);
    EXPECT_LE(short_move.top_clocks, 2);
    EXPECT_LT(short_move.jerk_clocks, full.jerk_clocks);
    EXPECT_GT(short_move.jerk_clocks, 0);
}

// The stretches the event model runs (a whole phase of the acceleration each) hold the header's acceleration,
// jerk x min(i + 1, n_j, T - i), on every clock from any clock of the acceleration to the end of its phase.
TEST(ScurvePlan, ItsStretchesHoldTheAccelerationOfEveryClock) {
    const std::uint32_t jerk = 0xFFFF'FFFF;
    for (const auto& [n_j, n_a] : std::vector<std::pair<std::int64_t, std::int64_t>>{{1, 0}, {3, 0}, {3, 2}, {5, 7}}) {
        const ScurvePlan p{n_j, n_a, jerk};
        const std::int64_t t = 2 * n_j + n_a;
        for (std::int64_t from = 0; from < t; ++from) {
            SCOPED_TRACE(testing::Message() << "n_j " << n_j << " n_a " << n_a << " from clock " << from);
            const RampStretch s = p.stretch_at(from, true);
            EXPECT_TRUE(s.slowing);
            ASSERT_GE(s.length, 1);
            const std::int64_t end = from + s.length;
            ASSERT_LE(end, t);
            const auto k_of = [&](std::int64_t i) { return std::min({i + 1, n_j, t - i}); };
            // The phase ends where the acceleration's law changes: at the top's first or last clock, or at T.
            EXPECT_TRUE(end == t || end == n_j || end == n_j + n_a) << end;
            for (std::int64_t i = from; i < end; ++i) {
                const std::uint64_t accel = s.accel + static_cast<std::uint64_t>(s.jerk * (i - from));
                EXPECT_EQ(accel, std::uint64_t{jerk} * static_cast<std::uint64_t>(k_of(i))) << "clock " << i;
            }
        }
    }
}

}  // namespace
}  // namespace cnc::fpga
