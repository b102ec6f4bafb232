// What a controller that runs a planned trajectory should have done, for the metrics: one MoveSpec per programmed
// move over the planner's move windows, and the commanded timed trajectory (the planner's profile as the
// controller's trajectory clock ran it: a servo's tau(t), or t itself for a controller that runs the plan as
// planned).
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "common/geometry.hpp"
#include "host/core/planner/plan_feed.hpp"
#include "host/core/planner/trajectory.hpp"
#include "host/servo/core/trajectory_clock.hpp"
#include "metrics/run_input.hpp"

namespace cnc::sim {

// The axes' step grid: machine position at step count 0, and steps per mm of each axis.
struct StepGrid {
    geom::Vec2 origin_mm;
    std::array<double, 2> steps_per_mm{};
};

// Windows: [depart(tau_begin), depart(tau_end)] of each move's planner window on the trajectory clock, so a hold
// at a rest point (the host landing the axes) belongs to the move that ends there. Corner blends lie between
// windows and count with the move before them (metrics MoveTimeline). End points are the programmed ones on the
// step grid (origin + round(steps)), the targets a controller lands on; a rapid's feed is its planned peak speed.
class PlannedMoves {
public:
    // `plan` must outlive this; the moves taken are dropped from it.
    PlannedMoves(host::planner::PlanFeed& plan, const StepGrid& grid) : m_plan(plan), m_grid(grid) {}
    // The moves not taken yet whose window the trajectory clock has left, so that both ends are known (every one
    // left once the run has `ended`: the rest of the job is planned then).
    [[nodiscard]] std::vector<metrics::MoveSpec> take(const host::servo::TrajectoryClock& clock, bool ended);

    // What take() still reads of the trajectory clock: at(t) from t_ps on, depart_time(tau) from tau_s on.
    struct ClockNeeded {
        TimePs t_ps;
        double tau_s;
    };
    [[nodiscard]] ClockNeeded clock_needed();

private:
    [[nodiscard]] geom::Vec2 on_grid(geom::Vec2 p, std::array<std::int64_t, 2>& steps) const;

    host::planner::PlanFeed& m_plan;
    StepGrid m_grid;
    std::size_t m_next = 0;
    // The next move's start, read as soon as the clock has left it, so that the knots before it can go.
    std::optional<TimePs> m_next_begin_ps;
};

// The earliest time the streaming metrics may still read the commanded trajectory at, once they have measured up to
// measured_ps: a sync window and a scan step (step_crossings' grid) before the first piece, tool sample or STEP/DIR
// edge they still hold, or before measured_ps (what comes later is later).
TimePs commanded_read_from(const metrics::RunInput& pending, TimePs measured_ps);

// The planner's state at tau(t) (velocity scaled by d tau/dt), from the origin of the step grid; `scan_step_ps`:
// step_crossings' grid, within which no axis velocity turns twice (a servo's period: tau is linear within it). The
// trajectory is shared with the closure; the clock is copied as it is at the call.
metrics::CommandedTrajectory commanded_trajectory(std::shared_ptr<const host::planner::Trajectory> traj,
                                                  const host::servo::TrajectoryClock& clock, geom::Vec2 origin_mm,
                                                  TimePs scan_step_ps);
// The same on the clock as it runs (the clock must outlive it): known up to the clock's last knot, which the caller
// copies into t_begin_ps/t_end_ps as the run goes (commanded_known).
metrics::CommandedTrajectory commanded_trajectory_live(std::shared_ptr<const host::planner::Trajectory> traj,
                                                       const host::servo::TrajectoryClock& clock, geom::Vec2 origin_mm,
                                                       TimePs scan_step_ps);
void commanded_known(metrics::CommandedTrajectory& c, const host::servo::TrajectoryClock& clock);
// The same for a controller that runs the plan as planned (tau = t, d tau/dt = 1): the planner's state at t itself,
// known up to the clock's last knot (commanded_known as the run goes), the clock copied or read by nobody. Read
// through the clock instead, tau(t) would be interpolated between its knots, which lie where the run's slices ended:
// their length follows the wall time (simulate.cpp), and an interpolation between other knots rounds tau
// differently in its last bit, which moves a half-step crossing by a picosecond.
metrics::CommandedTrajectory commanded_as_planned(std::shared_ptr<const host::planner::Trajectory> traj,
                                                  const host::servo::TrajectoryClock& clock, geom::Vec2 origin_mm,
                                                  TimePs scan_step_ps);

}  // namespace cnc::sim
