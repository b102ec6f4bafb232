// What the spi-fpga run should have done, for the metrics: one MoveSpec per programmed move over the planner's
// move windows, the commanded timed trajectory (the planner's profile as the host's trajectory clock ran it), and
// the commanded step rate of every rate word the FPGA applied.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "fpga/spi/spi_fpga_top.hpp"
#include "host/core/planner/plan_feed.hpp"
#include "host/core/planner/trajectory.hpp"
#include "host/servo/core/servo_core.hpp"
#include "metrics/run_input.hpp"

namespace cnc::sim {

// Windows: [depart(tau_begin), depart(tau_end)] of each move's planner window on the trajectory clock, so a hold
// at a rest point (the host landing the axes) belongs to the move that ends there. Corner blends lie between
// windows and count with the move before them (metrics MoveTimeline). End points are the programmed ones on the
// step grid (origin + round(steps)), the targets the host lands on; a rapid's feed is its planned peak speed.
class PlannedMoves {
public:
    // `plan` must outlive this; the moves taken are dropped from it.
    explicit PlannedMoves(host::planner::PlanFeed& plan) : m_plan(plan) {}
    // The moves not taken yet whose window the trajectory clock has left, so that both ends are known (every one
    // left once the run has `ended`: the rest of the job is planned then).
    [[nodiscard]] std::vector<metrics::MoveSpec> take(const host::servo::ServoCore& servo, bool ended);

    // What take() still reads of the trajectory clock: at(t) from t_ps on, depart_time(tau) from tau_s on.
    struct ClockNeeded {
        TimePs t_ps;
        double tau_s;
    };
    [[nodiscard]] ClockNeeded clock_needed();

private:
    host::planner::PlanFeed& m_plan;
    std::size_t m_next = 0;
    // The next move's start, read as soon as the clock has left it, so that the knots before it can go.
    std::optional<TimePs> m_next_begin_ps;
};

// The earliest time the streaming metrics may still read the commanded trajectory at, once they have measured up to
// measured_ps: a sync window and a scan step (step_crossings' grid) before the first piece, tool sample or STEP/DIR
// edge they still hold, or before measured_ps (what comes later is later).
TimePs commanded_read_from(const metrics::RunInput& pending, TimePs measured_ps);

// The planner's state at tau(t) (velocity scaled by d tau/dt). The trajectory is shared with the closure; the
// clock is the servo's as it is at the call.
metrics::CommandedTrajectory commanded_trajectory(std::shared_ptr<const host::planner::Trajectory> traj,
                                                  const host::servo::ServoCore& servo);
// The same on the servo's clock as it runs (the servo must outlive it): known up to the clock's last knot, which
// the caller copies into t_begin_ps/t_end_ps as the run goes (commanded_known).
metrics::CommandedTrajectory commanded_trajectory_live(std::shared_ptr<const host::planner::Trajectory> traj,
                                                       const host::servo::ServoCore& servo);
void commanded_known(metrics::CommandedTrajectory& c, const host::servo::ServoCore& servo);

// Per axis: one segment per stretch of one applied word (the host resends an unchanged word every period), from
// the edge it governs from, with the mean of the host's requested |rate| over the stretch (0 for a stop word): the
// metrics' runs, whose rate error is then the period rounding. Handed over once a stretch is closed (a different
// word was applied; its mean is final then), every one once the run has `ended`. The applied words are taken
// from the FPGA and folded into the open stretch as they come, so that neither they nor the servo's records
// before first_needed_period() are kept.
class RateSegments {
public:
    [[nodiscard]] std::vector<std::vector<metrics::RateSegment>> take(fpga::SpiFpgaTop& fpga,
                                                                      const host::servo::ServoCore& servo, bool ended);
    // The first servo period whose record a word not taken yet may read (each axis applies its words in frame
    // order, one frame per period).
    [[nodiscard]] std::uint64_t first_needed_period() const;

private:
    struct Stretch {
        TimePs t_ps = 0;  // its first word's
        spi::AxisRate rate;
        double requested_sum_steps_per_s = 0.0;  // of |the host's requested rate|, word by word
        std::size_t words = 0;
    };
    std::array<std::optional<Stretch>, host::servo::kAxes> m_open;
    std::array<std::uint64_t, host::servo::kAxes> m_next_seq{};  // [axis] after the last word's frame
};

}  // namespace cnc::sim
