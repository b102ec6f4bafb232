// step_gen (Π.5) for one accepted motion packet, as a schedule of register edges instead of a ticked FSM:
// the period arithmetic of DIR_WAIT and the cycle of every busy/DIR/STEP edge, generated lazily (a move can
// have millions of edges).
//
// Timeline, in edges after the edge k at which pkt_valid is high (seed 000 §5.2.4, derived from the listing):
//   k+1  IDLE sees pkt_valid: busy <= 1                        (kBusyRise)
//   k+2  SETUP: dir <= (steps >= 0), abs <= |steps|             (kDirEdge)
//   k+3  first DIR_WAIT edge: rem, cnt, periods                (kPeriodsEdge)
//   k+3+DIR_SETTLE  first RUN edge: both STEPs rise (run_start, 203 for DIR_SETTLE 200)
//   RUN lasts N = max over stepping axes of abs*period edges (abs_dom*period_dom; at least 1 edge when
//   some abs > 0 but no axis steps), then DONE at k+run_start+N drops busy (busy_fall); a zero-length move
//   goes DIR_WAIT -> DONE, so busy falls at k+run_start.
//   IDLE again at busy_fall+1: the first edge that accepts the next pkt_valid or cfg_valid (idle_from).
// Per stepping axis (rem > 0, period P > 0), RUN edge j = m*P raises STEP and j = m*P+PULSE_HIGH lowers it;
// if P <= PULSE_HIGH, cnt never reaches PULSE_HIGH and STEP stays high until the axis runs out of steps
// (one long pulse). The exit edge N-1 forces both STEPs low, overriding a rise on that edge.
// With the trapezoidal ramp (fpga.ramp) RUN steps on the clocks core/step_ramp.hpp gives, at the packet's period at
// most (never faster than 2 PULSE_HIGH a step); each STEP falls PULSE_HIGH clocks after it rose, the last fall is
// the exit edge N-1 and busy falls at N.
#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "fpga/core/fpga_config.hpp"
#include "fpga/core/step_ramp.hpp"
#include "fpga/core/uart_timing.hpp"

namespace cnc::fpga {

// SETUP: abs = steps[31] ? ~steps+1 : steps (so INT32_MIN gives 2^31).
[[nodiscard]] std::uint32_t abs_steps(std::int32_t steps);
// SETUP: dir = (steps[31] == 0): positive and zero counts give DIR = 1.
[[nodiscard]] constexpr bool dir_level(std::int32_t steps) {
    return steps >= 0;
}

struct StepPeriods {
    std::uint32_t x_cycles = 0;
    std::uint32_t y_cycles = 0;
    bool overflow = false;  // the 32-bit product (num/feed)*abs_dom exceeded 2^32-1 (computed in either mode)
};

// DIR_WAIT's first edge. feed 0 -> both feed_zero_period (uncoordinated); both abs 0 -> 0, 0; otherwise the dominant
// axis (X on a tie) gets num_dom/feed and the other (num_dom/feed)*abs_dom/abs_sub, or 0 if it does not move.
// Wrap32 takes the product mod 2^32 like the appendix. Exact uses the 64-bit product; a quotient that does not
// fit the 32-bit period register saturates at 2^32-1 cycles (85.9 s between steps), see models/fpga/README.md.
[[nodiscard]] StepPeriods compute_periods(std::uint32_t abs_x, std::uint32_t abs_y, std::uint16_t feed,
                                          std::uint32_t num_x, std::uint32_t num_y, const FpgaConfig& cfg);

enum class StepPin : std::uint8_t { Busy, DirX, DirY, StepX, StepY };

struct PinEdge {
    std::int64_t cycle = 0;  // edges after the pkt_valid edge k
    StepPin pin = StepPin::Busy;
    bool level = false;
};

struct MoveInputs {
    std::int32_t steps_x = 0;
    std::int32_t steps_y = 0;
    std::uint16_t feed = 0;
    std::uint32_t num_x = 0;  // step_gen's latched numerators
    std::uint32_t num_y = 0;
    std::uint32_t ramp_accel = 0;  // with a ramp: its latched registers (step_ramp.hpp)
    std::uint32_t ramp_start = 0;
    std::uint32_t ramp_jerk = 0;  // with the S-curve
};

// With the ramp: its inputs for a move (the dominant axis is X on a tie).
[[nodiscard]] RampInputs ramp_inputs(const MoveInputs& in, const FpgaConfig& cfg);

// How long step_gen stays in RUN for one packet: N clocks (above), dominant steps x NUMERATOR / feed for a
// coordinated move. What a host can expect a move to take, e.g. to size its ACK timeout.
[[nodiscard]] TimePs run_duration_ps(const MoveInputs& in, const FpgaConfig& cfg);

// STEP register changes of one axis during RUN (edges relative to the first RUN edge).
class AxisPulses {
public:
    AxisPulses() = default;
    AxisPulses(std::uint32_t steps, std::uint32_t period_cycles, std::uint32_t pulse_high_cycles,
               std::int64_t exit_edge);
    [[nodiscard]] bool peek(CycleEdge& out) const;
    void pop();

private:
    std::int64_t m_steps = 0;
    std::int64_t m_period = 0;
    std::int64_t m_high = 0;
    std::int64_t m_exit = 0;
    bool m_separate = false;  // P > PULSE_HIGH: one pulse per period
    std::int64_t m_pulse = 0;
    bool m_rising = true;
    bool m_done = true;
};

// STEP register changes of both axes during a ramped RUN: a step's rises on its clock (X first), its falls
// PULSE_HIGH clocks later, before the next step's rises.
class RampPulses {
public:
    RampPulses() = default;
    RampPulses(const RampInputs& in, bool x_dominant, std::uint32_t pulse_high_cycles);
    // The next edge (cycle relative to the first RUN edge); false after the last fall.
    bool next(PinEdge& out);

private:
    std::optional<RampRun> m_run;
    bool m_x_dominant = true;
    std::int64_t m_high = 0;
    std::array<PinEdge, 4> m_pending{};
    std::size_t m_pending_size = 0;
    std::size_t m_pending_next = 0;
};

class StepSchedule {
public:
    static constexpr std::int64_t kBusyRise = 1;
    static constexpr std::int64_t kDirEdge = 2;
    static constexpr std::int64_t kPeriodsEdge = 3;

    // dir_*_before: the DIR levels left by the previous move (0 after reset).
    StepSchedule(const MoveInputs& in, bool dir_x_before, bool dir_y_before, const FpgaConfig& cfg);

    [[nodiscard]] const StepPeriods& periods() const { return m_periods; }
    [[nodiscard]] bool dir_x() const { return m_dir_x; }
    [[nodiscard]] bool dir_y() const { return m_dir_y; }
    [[nodiscard]] bool has_run() const { return m_has_run; }  // false: zero-length, no RUN state
    [[nodiscard]] std::int64_t run_start() const { return m_run_start; }
    [[nodiscard]] std::int64_t run_cycles() const { return m_run_cycles; }  // N (0 without RUN)
    [[nodiscard]] std::int64_t busy_fall() const { return m_run_start + m_run_cycles; }
    [[nodiscard]] std::int64_t idle_from() const { return busy_fall() + 1; }

    // The next edge in cycle order (ties: busy, dir_x, dir_y, step_x, step_y); false after the busy fall.
    bool next(PinEdge& out);

private:
    void start_ramp(const MoveInputs& in, std::uint32_t abs_x, std::uint32_t abs_y, const FpgaConfig& cfg);

    StepPeriods m_periods;
    bool m_dir_x;
    bool m_dir_y;
    bool m_has_run;
    std::int64_t m_run_start;
    std::int64_t m_run_cycles = 0;
    std::array<PinEdge, 3> m_prologue{};
    std::size_t m_prologue_size = 0;
    std::size_t m_prologue_next = 0;
    AxisPulses m_x;
    AxisPulses m_y;
    std::optional<RampPulses> m_ramp;
    bool m_busy_fall_sent = false;
};

}  // namespace cnc::fpga
