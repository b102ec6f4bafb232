// The ideal controller's pins over a planned job, without SystemC: each axis steps where the plan's position
// crosses a half-step level (metrics::step_crossings: a quantiser that rounds the planned position to the nearest
// step), with the edges a DRV8825 needs (step_train.hpp); the laser follows the job's intent move by move. Made a
// scan interval at a time as they are asked for, ahead of the simulation that drives them, so that a long job is
// held as the plan's look-ahead.
#pragma once
#include <array>
#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "architectures/ideal/step_train.hpp"
#include "architectures/planner/planned_moves.hpp"
#include "host/core/planner/plan_feed.hpp"
#include "metrics/run_input.hpp"

namespace cnc::sim::ideal {

enum class Pin { StepX, DirX, StepY, DirY, Laser };

struct TimedEdge {
    TimePs t_ps = 0;
    Pin pin = Pin::StepX;
    bool level = false;
};

class IdealEdges {
public:
    // `plan` is read from its start; `end_ps` is the planned job's end (the trajectory's duration); the crossings
    // are searched `scan_step_ps` at a time (within which no axis velocity turns twice).
    IdealEdges(std::shared_ptr<host::planner::PlanFeed> plan, const StepGrid& grid, TimePs end_ps, TimePs scan_step_ps);

    // The next edge in time order (a STEP, DIR or laser level); none after the last.
    [[nodiscard]] std::optional<TimedEdge> next();

    // The commanded step rate of each axis as it changes, from the step it governs (metrics::RateSegment): a stretch
    // of constant commanded velocity (a line at its cruise speed) is one segment, and elsewhere (ramps, arcs,
    // blends) each step has its own, the planned rate at its instant. Handed over up to before_ps.
    [[nodiscard]] std::vector<std::vector<metrics::RateSegment>> take_rate_segments(TimePs before_ps);

private:
    struct AxisState {
        StepTrain train;
        std::deque<PinEdge> edges;  // made, not handed over
        std::deque<metrics::RateSegment> segments;
        std::optional<double> cruise_rate;  // the open segment's rate while the commanded velocity is constant
    };

    void scan();
    void add_steps(std::size_t axis, TimePs from_ps, TimePs to_ps);
    void add_laser_until(TimePs t_ps);
    void laser_at(TimePs t_ps, bool on);
    // The scan interval's start at or before the next motion after t_ps (the plan's next piece), so that a rest
    // (a dwell, an operator pause) is not scanned interval by interval.
    [[nodiscard]] TimePs next_motion_scan_ps(TimePs t_ps);
    [[nodiscard]] TimePs final_until_ps() const;

    std::shared_ptr<host::planner::PlanFeed> m_plan;
    StepGrid m_grid;
    TimePs m_end_ps;
    TimePs m_scan_step_ps;
    metrics::CommandedTrajectory m_commanded;
    std::array<AxisState, 2> m_axes;
    TimePs m_scanned_ps = 0;  // every step and laser edge up to here is made
    bool m_done = false;

    // The laser: the moves read so far, and the level it was last set to.
    std::size_t m_next_move = 0;
    std::optional<std::pair<double, bool>> m_previous_move;  // its window's end and laser intent
    bool m_laser_on = false;
    std::deque<TimedEdge> m_laser_edges;
};

}  // namespace cnc::sim::ideal
