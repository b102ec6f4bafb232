// step_gen's trapezoidal ramp (fpga/core/step_ramp.hpp): the event model's step clocks against the registers
// updated clock by clock as the header states them, and against the kinematics of constant acceleration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fpga/core/step_ramp.hpp"
#include "fpga/core/step_schedule.hpp"
#include "ramp_step.hpp"

namespace cnc::fpga {
namespace {

using Step = test::RampStep;

std::vector<RampRun::Step> ramp_steps(const RampInputs& in) {
    RampRun run(in);
    std::vector<RampRun::Step> out;
    RampRun::Step s;
    while (run.next(s)) out.push_back(s);
    return out;
}

std::vector<Step> event_steps(const RampInputs& in) {
    std::vector<Step> out;
    for (const RampRun::Step& s : ramp_steps(in)) out.push_back({s.clock, s.sub});
    return out;
}

// The header's register updates, one clock at a time.
std::vector<Step> clock_by_clock(const RampInputs& in) {
    const auto a = static_cast<std::int64_t>(in.accel_reg);
    const std::int64_t start =
        std::max<std::int64_t>(std::min<std::int64_t>(std::int64_t{in.start_reg} * 65'536, in.cruise), 1);
    const auto cruise = static_cast<std::int64_t>(in.cruise);
    const std::int64_t one = std::int64_t{1} << 48;
    std::int64_t phase = one - start;
    std::int64_t v = start;
    enum { Accel, Cruise, Decel } state = Accel;
    std::int64_t done = 0;
    std::int64_t ramp_steps = 0;
    std::int64_t error = in.abs_dom / 2;
    std::vector<Step> out;
    for (std::int64_t j = 0; done < in.abs_dom; ++j) {
        phase += v;
        if (phase >= one) {
            phase -= one;
            ++done;
            error += in.abs_sub;
            const bool sub = error >= in.abs_dom;
            if (sub) error -= in.abs_dom;
            out.push_back({j, sub});
        }
        const auto slow_down = [&] { v = std::max(v - a, start); };
        if (state == Accel) {
            if (2 * done > in.abs_dom) {
                state = Decel;
                slow_down();
            } else if (v + a >= cruise) {
                v = cruise;
                ramp_steps = done;
                state = Cruise;
            } else {
                v += a;
            }
        } else if (state == Cruise) {
            if (in.abs_dom - done < ramp_steps) {
                state = Decel;
                slow_down();
            }
        } else {
            slow_down();
        }
    }
    return out;
}

// Velocity in 2^-48 steps per clock of one step every `period` clocks; the start register of that velocity.
constexpr std::uint64_t velocity(double period) {
    return static_cast<std::uint64_t>(static_cast<double>(kPhaseOne) / period);
}
constexpr std::uint32_t start_reg(double period) {
    return static_cast<std::uint32_t>(velocity(period) >> kStartShift);
}

TEST(RampRun, StepsOnTheClocksTheRegistersGiveClockByClock) {
    // From a step every 4000 clocks to one every 400 in about 10,000 clocks.
    const std::uint32_t accel = static_cast<std::uint32_t>((velocity(400) - velocity(4000)) / 10'000);
    const std::vector<RampInputs> cases = {
        {200, 77, velocity(400), start_reg(4000), accel},   // accelerates, cruises, decelerates
        {201, 201, velocity(400), start_reg(4000), accel},  // odd count, the other axis on every step
        {12, 5, velocity(400), start_reg(4000), accel},     // turns round before the cruise
        {1, 0, velocity(400), start_reg(4000), accel},
        {2, 1, velocity(400), start_reg(4000), accel},
        {50, 3, velocity(400), start_reg(4000), 0},      // no acceleration: all at the start speed
        {50, 20, velocity(900), start_reg(400), accel},  // starts above the cruise: all at the cruise
        {300, 299, velocity(250), start_reg(2500), accel * 7},
    };
    for (const RampInputs& in : cases) {
        SCOPED_TRACE(testing::Message() << "abs " << in.abs_dom << "/" << in.abs_sub << " accel " << in.accel_reg);
        const std::vector<Step> expected = clock_by_clock(in);
        ASSERT_EQ(expected.size(), in.abs_dom);
        EXPECT_EQ(event_steps(in), expected);
    }
}

TEST(RampRun, TheOtherAxisMakesItsStepsAtTheNearestDominantStep) {
    const RampInputs in{1000, 333, velocity(400), start_reg(4000), 20'000'000};
    const std::vector<Step> steps = event_steps(in);
    ASSERT_EQ(steps.size(), 1000U);
    std::int64_t sub = 0;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        if (steps[k].sub) ++sub;
        // After k+1 dominant steps the other axis is at round((k+1) x 333 / 1000), halves down.
        const double ideal = static_cast<double>(k + 1) * 333.0 / 1000.0;
        EXPECT_LE(std::abs(static_cast<double>(sub) - ideal), 0.5) << "dominant step " << k + 1;
    }
    EXPECT_EQ(sub, 333);
}

// The kinematics of constant acceleration a from v0: the n-th step (from 0) at the time t with v0 t + a t^2 / 2 = n.
TEST(RampRun, AcceleratesAndDeceleratesAtTheRegistersRate) {
    const double v0 = 1.0 / 4000;  // steps per clock
    const double vc = 1.0 / 400;
    const double a = (vc - v0) / 20'000;  // steps per clock^2: 20,000 clocks up, 20,000 down
    const RampInputs in{2000, 0, velocity(400), start_reg(4000),
                        static_cast<std::uint32_t>(std::round(a * static_cast<double>(kPhaseOne)))};
    const std::vector<Step> steps = event_steps(in);
    ASSERT_EQ(steps.size(), 2000U);
    // Up: the n-th step where the distance travelled since the first reaches n, within a clock's step (the
    // registers' rounding of a and v0 is below 1e-4).
    const double up_steps = (vc * vc - v0 * v0) / (2 * a);  // 27.5
    for (int n = 1; n < static_cast<int>(up_steps); ++n) {
        const double t = (-v0 + std::sqrt(v0 * v0 + 2 * a * n)) / a;
        EXPECT_NEAR(static_cast<double>(steps[static_cast<std::size_t>(n)].clock - steps[0].clock), t, 0.02 * t + 2)
            << "step " << n;
    }
    // Cruise: one step every 400 clocks (the velocity register floors 2^48 / 400: never faster), on every step
    // marked cruising after the first, and the ramps' 27 or 28 steps each side are not.
    const std::vector<RampRun::Step> marked = ramp_steps(in);
    std::size_t cruising = 0;
    for (std::size_t k = 1; k < marked.size(); ++k) {
        if (!marked[k].cruising || !marked[k - 1].cruising) continue;
        ++cruising;
        EXPECT_EQ(marked[k].clock - marked[k - 1].clock, 400) << "step " << k;
    }
    EXPECT_GE(cruising, 2000U - 2 * 29);
    EXPECT_LE(cruising, 2000U - 2 * 27);
    // First to last step: 1999 steps at vc plus (vc - v0)^2 / (a vc) for the two ramps (18,000 clocks), within a
    // step at the start speed.
    const double expected = 1999 / vc + (vc - v0) * (vc - v0) / (a * vc);
    EXPECT_NEAR(static_cast<double>(steps.back().clock - steps.front().clock), expected, 1 / v0);
    // Down mirrors up within half a step: each spacing of the slowing down lies between the spacing the same
    // distance from the start and the next one (the deceleration starts once fewer steps are left than the
    // acceleration took, so it ends between the start speed and the speed one step later: no step crawls at the
    // start speed).
    const auto spacing_from_end = [&](std::size_t k) {
        return steps[steps.size() - k].clock - steps[steps.size() - k - 1].clock;
    };
    const auto spacing_from_start = [&](std::size_t k) { return steps[k].clock - steps[k - 1].clock; };
    for (std::size_t k = 1; k < 20; ++k) {
        EXPECT_LE(spacing_from_start(k + 1), spacing_from_end(k)) << "spacing " << k;
        EXPECT_LE(spacing_from_end(k), spacing_from_start(k)) << "spacing " << k;
    }
}

TEST(RampRun, TheVelocityOfAPeriodIsHeldToTheShortestPeriod) {
    EXPECT_EQ(velocity_of_period(400, 200), kPhaseOne / 400);
    EXPECT_EQ(velocity_of_period(150, 200), kPhaseOne / 200);  // 2 PULSE_HIGH: STEP low as long as high
    EXPECT_EQ(velocity_of_period(0, 0), kPhaseOne);
}

TEST(StepSchedule, ARampedMoveRisesOnTheRampsClocksAndEndsAfterTheLastPulse) {
    FpgaConfig cfg;
    cfg.ramp = StepRamp::Trapezoidal;
    // 160 steps/mm at F3000 (50 mm/s): 6250 clocks a step at cruise; 1000 mm/s^2 and a 5 mm/s start.
    const MoveInputs in{1600, -400, 3000, 18'750'000, 18'750'000, cfg.ramp_accel_default, cfg.ramp_start_default};
    StepSchedule s(in, false, false, cfg);
    const std::vector<Step> steps = event_steps(
        {1600, 400, velocity_of_period(18'750'000 / 3000, 200), cfg.ramp_start_default, cfg.ramp_accel_default});
    std::vector<Step> rises;
    std::int64_t last_x_fall = -1;
    std::int64_t y_rises = 0;
    PinEdge e;
    while (s.next(e)) {
        if (e.pin == StepPin::StepX && e.level) rises.push_back({e.cycle - s.run_start(), false});
        if (e.pin == StepPin::StepY && e.level) {
            ++y_rises;
            ASSERT_FALSE(rises.empty());
            EXPECT_EQ(e.cycle - s.run_start(), rises.back().clock);  // with a dominant step
            rises.back().sub = true;
        }
        if (e.pin == StepPin::StepX && !e.level) {
            EXPECT_EQ(e.cycle - s.run_start(), rises.back().clock + cfg.pulse_high_cycles);
            last_x_fall = e.cycle;
        }
        if (e.pin == StepPin::Busy && !e.level) {
            EXPECT_EQ(e.cycle, last_x_fall + 1);
        }
    }
    EXPECT_EQ(rises, steps);
    EXPECT_EQ(y_rises, 400);
    EXPECT_EQ(s.busy_fall(), last_x_fall + 1);
    // 1599 steps at 8000 steps/s; the ramps from and to 5 mm/s at 1000 mm/s^2 add (50 - 5)^2 / (1000 x 50) s;
    // within a step at the start speed (1.25 ms).
    const double run_s = static_cast<double>(run_duration_ps(in, cfg)) * 1e-12;
    EXPECT_NEAR(run_s, 1599.0 / 8000 + 45.0 * 45.0 / (1000.0 * 50.0), 1.25e-3);
}

}  // namespace
}  // namespace cnc::fpga
