// step_gen's trapezoidal ramp (fpga.ramp = "trapezoidal", our option on seed 000 §7.2's proposal of trapezoidal
// ramps on the FPGA): which clocks of RUN the dominant axis steps on, and whether the other axis steps with it.
//
// The registers, updated on every RUN clock j = 0, 1, ...:
//   phase  += velocity                 (48 bits; its carry out is a dominant step at clock j)
//   then, with `done` the dominant steps so far and `ramp_steps` those the acceleration took:
//   ACCEL:  2 done > abs_dom            -> DECEL (and the DECEL update below)
//           velocity + accel >= cruise  -> velocity = cruise, ramp_steps = done, CRUISE
//           else                        -> velocity += accel
//   CRUISE: abs_dom - done < ramp_steps -> DECEL (and the DECEL update)
//   DECEL:  velocity = max(velocity - accel, start)
// velocity starts at `start` and phase at 2^48 - start, so that the first step is on the first RUN clock as in the
// seed. The deceleration begins when the steps left are fewer than the acceleration took (its first step came on
// the first clock, with no period before it), so the periods of the slowing down mirror those of the speeding up
// (to the phase the cruise left in the accumulator) and the last period is never longer than the first; a short
// move turns round past half its steps. The other axis steps at a dominant step when
// Bresenham's error, which starts at abs_dom / 2 (the nearest step), reaches abs_dom: grbl's stepper does the same.
// Fixed point: velocity in 2^-48 steps per clock, the acceleration register in 2^-48 steps per clock^2, the start
// register in 2^-32 steps per clock (the velocity's top 32 fraction bits).
//
// The S-curve (fpga.ramp = "s-curve", on seed 000 §7.2's proposal of S-curve ramps) keeps the phase, the velocity
// and the step-count turn of the deceleration, and makes the velocity's change per clock jerk-limited. At the
// move's start step_gen plans (core/scurve_plan.hpp) the clocks n_j of each jerk phase and n_a at the top
// acceleration; then, on the clocks i = 0 .. T-1 of the acceleration (T = 2 n_j + n_a):
//   accel   = jerk x min(i + 1, n_j, T - i)     (2^-80 steps per clock^2: grows by the jerk register each clock,
//                                                holds, falls back by it to 0)
//   velocity += accel >> 32
// then CRUISE at the velocity reached, until fewer steps are left than the acceleration took; then the
// deceleration subtracts the same T increments (they read the same backwards), so it mirrors the acceleration
// and ends exactly at the start speed, which the last steps keep.
#pragma once
#include <cstdint>

#include "fpga/core/ramp_stretch.hpp"
#include "fpga/core/scurve_plan.hpp"

namespace cnc::fpga {

inline constexpr int kPhaseBits = 48;
inline constexpr std::uint64_t kPhaseOne = std::uint64_t{1} << kPhaseBits;  // one step
inline constexpr int kStartShift = kPhaseBits - 32;                         // the start register's place

struct RampInputs {
    std::uint32_t abs_dom = 0;    // steps of the axis with more (X on a tie)
    std::uint32_t abs_sub = 0;    // steps of the other
    std::uint64_t cruise = 0;     // velocity at the packet's feed, 2^-48 steps per clock
    std::uint32_t start_reg = 0;  // the init packet's start speed, 2^-32 steps per clock
    std::uint32_t accel_reg = 0;  // the init packet's acceleration, 2^-48 steps per clock^2
    std::uint32_t jerk_reg = 0;   // with the S-curve: the init packet's jerk, 2^-80 steps per clock^3 (0: trapezoid)
};

// The velocity of a dominant-axis period: one step every `period_cycles` clocks, held to one step every
// `min_period_cycles` (floor: the ramp's steps never come faster than the packet asks).
[[nodiscard]] std::uint64_t velocity_of_period(std::uint64_t period_cycles, std::uint64_t min_period_cycles);

// The velocity a move starts and ends at: the start register, at most the cruise; a start register of 0 still steps,
// at the slowest velocity the register holds.
[[nodiscard]] std::uint64_t ramp_start_velocity(const RampInputs& in);

class RampRun {
public:
    struct Step {
        std::int64_t clock = 0;  // RUN clock j of the dominant step
        bool sub = false;        // the other axis steps on the same clock
        bool cruising = false;   // made in CRUISE (two such steps in a row are a period at the cruise apart)
    };

    explicit RampRun(const RampInputs& in);

    // The next dominant step; false once all abs_dom have been made.
    bool next(Step& out);

private:
    enum class Phase { Accel, Cruise, Decel };

    // The clocks from m_clock on until the acceleration's law changes.
    [[nodiscard]] RampStretch trapezoid_stretch() const;
    [[nodiscard]] RampStretch scurve_stretch();
    // After a stretch without a step.
    void end_stretch(const RampStretch& s);
    // The velocity register's update at the end of a clock that used velocity `v`.
    void update_after_step(std::uint64_t v, bool clamp_clock);
    void scurve_after_step(std::uint64_t v, const RampStretch& s, std::int64_t n);
    [[nodiscard]] std::uint64_t decelerated(std::uint64_t v) const;

    RampInputs m_in;
    std::uint64_t m_start;     // velocity at the start and the floor of the deceleration
    std::int64_t m_clock = 0;  // the next clock to run
    std::uint64_t m_phase;     // phase accumulator before m_clock
    std::uint64_t m_velocity;  // velocity m_clock uses
    Phase m_state = Phase::Accel;
    std::uint32_t m_done = 0;
    std::uint32_t m_ramp_steps = 0;
    std::uint64_t m_error;  // Bresenham's, of the other axis
    ScurvePlan m_plan;      // with the S-curve
    std::int64_t m_ramp_clock = 0;  // clocks of the S-curve's acceleration or deceleration so far
};

}  // namespace cnc::fpga
