// The servo thread's work in one period (seed 004 §4.3.2 driver contract: commanded velocity -> step frequency ->
// device, position back in the same full-duplex transfer), without SystemC: the shell (../servo_thread.hpp)
// calls step() at each wake-up with the reply of the previous transfer and sends the words it returns.
//
// Per period n (nominal start n * T):
//  1. Feedback: the step counters the FPGA captured when SS fell at the start of the previous transfer, widened
//     to 64 bits (spi::widen_count), and the FIFO level of that reply. No feedback before the first transfer:
//     the counters start at 0.
//  2. Trajectory clock tau (trajectory_clock.hpp): tau_n = min(tau_{n-1} + T, next rest point). Rest points are
//     the times at which the plan comes to rest: every programmed move end in exact-stop mode, reversals and
//     corners without a blend in continuous mode, and the job end. The host holds tau at a rest point until
//     every axis has landed on it (below), then runs on: an in-position check before the next move starts.
//     The plan is read as the clock runs (planner::PlanFeed): the next rest point is looked for only up to
//     tau_{n-1} + T, and its landing target worked out once it is found.
//  3. Tracking (stepgen_law.hpp, per axis, in steps from the origin): pos_cmd = planner position at tau_n;
//     pos_fb = the snapshot count + the rate of the word sent last period x T (the full-duplex reply is one
//     period old: the host extrapolates with the rate it commanded itself, which makes the loop hm2's, whose read
//     precedes its write in the same period). The count is taken as the position itself: a period-counter
//     generator rises at once when a word starts it and then every period, as a round-to-nearest quantiser of
//     a continuous position steps half a step before it reaches each new step, so its count is within half a
//     step of that position either way (the metrics' sync error and the landing use the same convention).
//     The law's velocity becomes a rate word (rate_word.hpp); vel_fb is that word's rate. The deadband is
//     host.deadband_steps while the generator runs (its estimate swings by a step with the generator's phase);
//     when the count is exact (the axis stands, see 4) it is half a step, so that a standing axis moves onto the
//     step nearest its command instead of keeping a one-step offset while the other axis runs.
//  4. Landing, while tau is held at a rest point (every axis; the period in which tau reaches the point still
//     tracks). Target = the commanded position at the rest point rounded to the nearest step (llround). A count
//     is final when the two previous frames were stops for the axis and the reply showed an empty FIFO: the
//     older stop was then read by the generator (a stopped or stopping generator never rises again), and the
//     reply's counters include every rise before that read (FPGA README: counters cover rises up to 2 edges
//     before the snapshot, the FIFO level frames not read before it). Until a count is final the host sends
//     stops. With a final count: equal to the target -> landed; else one landing pulse: a word of period
//     2 T in the direction of the target, followed by stops. A pulse gives at most one step: the next frame
//     (a stop) is written at most T + latency_max after the pulse frame (both end a transfer time after their
//     wake-ups), before the generator's second rise 2 T after its first (the scenario refuses latency_max +
//     transfer slot > T), and in both rate-apply modes a stop cancels the rise it reaches first. It may give
//     none (Immediately: the first rise is the last rise + 2 T when that is later), which only costs a retry.
//     So each landing step takes three periods (pulse, stop, stop), a pulse never takes the count past the
//     target, and landing ends with count == target exactly, with any latency.
//  5. When every axis has landed on the last rest point the job is done: step() returns Done and the shell
//     stops transferring.
//  6. Laser (laser_bit.hpp): the frame's laser bit is the job's intent over the stretch of plan the clock crossed
//     this period; off while landing (the clock is held) and at rest.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "host/core/planner/plan_feed.hpp"
#include "host/servo/core/laser_bit.hpp"
#include "host/servo/core/servo_config.hpp"
#include "host/servo/core/stepgen_law.hpp"
#include "host/servo/core/trajectory_clock.hpp"
#include "spi/core/spi_frame.hpp"

namespace cnc::host::servo {

enum class PeriodMode { Track, Land, Done };
[[nodiscard]] const char* to_string(PeriodMode m);

struct AxisPeriod {
    double pos_cmd_steps = 0.0;          // planner position at tau, in steps from the origin
    std::int64_t count = 0;              // widened counter of the feedback used
    double requested_steps_per_s = 0.0;  // the law's velocity (or the landing pulse's rate), signed
    spi::AxisRate word;                  // sent this period
    bool in_deadband = false;
};

struct PeriodRecord {
    std::int64_t n = 0;
    double tau_s = 0.0;
    double path_speed_mm_per_s = 0.0;  // planner path speed at tau while tracking; 0 while landing
    PeriodMode mode = PeriodMode::Track;
    std::uint32_t fifo_level = 0;  // of the feedback used
    std::array<AxisPeriod, kAxes> axes{};
    bool laser_on = false;  // sent this period (the frame's laser bit)
};

struct ServoStats {
    std::uint64_t landing_pulses = 0;
    std::uint64_t rest_points = 0;  // rest points of the plan (holds)
    std::uint64_t rest_points_landed = 0;
    std::uint64_t replies_dropped_flag = 0;   // replies reporting a frame dropped (FIFO full)
    std::uint64_t replies_rejected_flag = 0;  // replies reporting a rejected frame
};

// What the servo knows of the whole job before it starts (the job read once ahead of the run).
struct ServoJob {
    std::vector<bool> laser_intended;  // one entry per programmed move (laser_intent(program))
    std::uint64_t rest_points = 0;     // of the whole plan (count_rest_points), for the report
};

class ServoCore {
public:
    // `plan` (which must outlive this) is read as the clock runs: each rest point once the servo heads for it.
    ServoCore(const ServoConfig& cfg, planner::PlanFeed& plan, ServoJob job);

    // One servo period. `feedback`: the reply of the previous transfer (nullopt in the first period).
    const PeriodRecord& step(const std::optional<spi::Feedback>& feedback);

    [[nodiscard]] bool done() const { return m_done; }
    // The period records from log_first() on (drop_log_before drops the older ones once read).
    [[nodiscard]] const std::vector<PeriodRecord>& log() const { return m_log; }
    [[nodiscard]] std::uint64_t log_first() const { return m_log_first; }
    [[nodiscard]] std::uint64_t periods() const { return m_log_first + m_log.size(); }  // dropped or not
    [[nodiscard]] const PeriodRecord& record(std::uint64_t n) const { return m_log[n - m_log_first]; }
    void drop_log_before(std::uint64_t n);
    [[nodiscard]] const TrajectoryClock& clock() const { return m_clock; }
    // The clock's knots no reader needs any more (TrajectoryClock::drop_before).
    void drop_clock_before(TimePs t_ps, double tau_s) { m_clock.drop_before(t_ps, tau_s); }
    [[nodiscard]] const ServoStats& stats() const { return m_stats; }
    // The rest point the clock is held at while the axes land on it (none while tracking), and its landing
    // target per axis (counts).
    [[nodiscard]] std::optional<double> rest_point_s() const { return m_rest_s; }
    [[nodiscard]] const std::array<std::int64_t, kAxes>& target() const { return m_target; }
    [[nodiscard]] std::array<double, kAxes> position_steps(geom::Vec2 pos_mm) const;
    [[nodiscard]] const ServoConfig& config() const { return m_cfg; }

private:
    void track(PeriodRecord& rec);
    bool land(PeriodRecord& rec);  // true when every axis has landed
    // The feedback count is the axis's final position (header, step 4): the two previous words were stops and
    // the reply showed an empty FIFO.
    [[nodiscard]] bool count_is_exact(std::size_t axis) const;
    const PeriodRecord& finish(PeriodRecord& rec);

    const ServoConfig m_cfg;
    planner::PlanFeed& m_plan;
    const double m_period_s;
    const std::uint32_t m_land_period_cycles;
    std::array<StepgenParams, kAxes> m_params{};
    LaserBit m_laser;

    std::optional<double> m_rest_s;  // landing
    std::array<std::int64_t, kAxes> m_target{};
    double m_tau_s = 0.0;
    bool m_done = false;
    bool m_have_feedback = false;
    std::uint32_t m_fifo_level = 0;
    std::array<std::int64_t, kAxes> m_count{};
    std::array<StepgenState, kAxes> m_law{};
    std::array<spi::AxisRate, kAxes> m_word_prev{};   // frame n-1
    std::array<spi::AxisRate, kAxes> m_word_prev2{};  // frame n-2
    std::vector<PeriodRecord> m_log;
    std::uint64_t m_log_first = 0;
    TrajectoryClock m_clock;
    ServoStats m_stats;
};

// The plan's first rest point (see above) after `after_s` (the first of all without) if it is at or before
// `until_s`, planned as far as that; none otherwise. An empty plan has one, at 0; the last is the plan's end.
[[nodiscard]] std::optional<double> next_rest_point(planner::PlanFeed& plan, std::optional<double> after_s,
                                                    double until_s);
// Whether rest point `rest_s` is the plan's last (the end of the job).
[[nodiscard]] bool last_rest_point(planner::PlanFeed& plan, double rest_s);
// Every rest point of the plan, planned to its end (the pieces and moves searched dropped as it goes).
[[nodiscard]] std::uint64_t count_rest_points(planner::PlanFeed& plan);

}  // namespace cnc::host::servo
