#include "architectures/planner/planned_moves.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

#include "run/moves.hpp"

namespace cnc::sim {

namespace {

constexpr double kSecondsPerMinute = 60.0;
constexpr TimePs kEndOfTime = std::numeric_limits<TimePs>::max();

using ClockAt = std::function<host::servo::TrajectoryClock::Reading(TimePs)>;

metrics::CommandedTrajectory commanded_on(std::shared_ptr<const host::planner::Trajectory> traj, ClockAt clock_at,
                                          const host::servo::TrajectoryClock& clock, geom::Vec2 origin_mm,
                                          TimePs scan_step_ps) {
    metrics::CommandedTrajectory c;
    commanded_known(c, clock);
    c.origin_mm = origin_mm;
    c.scan_step_ps = scan_step_ps;
    c.state_at = [traj, clock_at = std::move(clock_at)](TimePs t) {
        const host::servo::TrajectoryClock::Reading r = clock_at(t);
        const host::planner::Sample s = traj->at(r.tau_s);
        return metrics::CommandedState{s.pos_mm, s.vel_mm_per_s * r.rate};
    };
    return c;
}

}  // namespace

// The programmed point on the step grid (what the controller lands on).
geom::Vec2 PlannedMoves::on_grid(geom::Vec2 p, std::array<std::int64_t, 2>& steps) const {
    const geom::Vec2 d = p - m_grid.origin_mm;
    steps = {std::llround(d.x_mm * m_grid.steps_per_mm[0]), std::llround(d.y_mm * m_grid.steps_per_mm[1])};
    return m_grid.origin_mm + geom::Vec2{static_cast<double>(steps[0]) / m_grid.steps_per_mm[0],
                                         static_cast<double>(steps[1]) / m_grid.steps_per_mm[1]};
}

std::vector<metrics::MoveSpec> PlannedMoves::take(const host::servo::TrajectoryClock& clock, bool ended) {
    const double tau_now_s = clock.tau_at(clock.t_end_ps());
    std::vector<metrics::MoveSpec> moves;
    for (; const host::planner::FedMove* fed = m_plan.move(m_next); ++m_next) {
        const std::size_t i = m_next;
        const auto& window = fed->window;
        if (!m_next_begin_ps && (ended || tau_now_s > window.first)) m_next_begin_ps = clock.depart_time(window.first);
        if (!ended && !(tau_now_s > window.second)) break;
        const host::ProgrammedMove& pm = fed->move;
        metrics::MoveSpec m;
        m.index = static_cast<int>(i) + 1;
        m.line = pm.line;
        m.programmed = static_cast<int>(i);
        m.path = pm.path;
        m.z_end_mm = pm.z_end_mm;
        std::array<std::int64_t, 2> from{};
        std::array<std::int64_t, 2> to{};
        m.from_mm = on_grid(pm.path.start, from);
        m.to_mm = on_grid(pm.path.end, to);
        m.steps = {to[0] - from[0], to[1] - from[1]};
        m.rapid = pm.kind == host::MotionKind::Rapid;
        const double peak = fed->peak_mm_per_s;
        set_path_feed(m, m.rapid && peak > 0.0 ? peak * kSecondsPerMinute : pm.feed_mm_per_min);
        m.t_begin_ps = *m_next_begin_ps;
        m.t_end_ps = clock.depart_time(window.second);
        m_next_begin_ps.reset();
        moves.push_back(m);
    }
    m_plan.drop_moves_before(m_next);
    return moves;
}

PlannedMoves::ClockNeeded PlannedMoves::clock_needed() {
    const host::planner::FedMove* fed = m_plan.move(m_next);
    if (fed == nullptr) return {kEndOfTime, std::numeric_limits<double>::infinity()};
    const auto& window = fed->window;
    if (!m_next_begin_ps) return {kEndOfTime, window.first};
    return {*m_next_begin_ps, window.second};
}

TimePs commanded_read_from(const metrics::RunInput& pending, TimePs measured_ps) {
    TimePs first_ps = measured_ps;
    if (!pending.moves.empty()) first_ps = std::min(first_ps, pending.moves.front().t_begin_ps);
    if (!pending.tool.empty()) first_ps = std::min(first_ps, pending.tool.front().t_ps);
    for (const metrics::AxisTrace& axis : pending.axes) {
        for (const EdgeLog* log : {&axis.step, &axis.dir}) {
            if (!log->edges.empty()) first_ps = std::min(first_ps, log->edges.front().t_ps);
        }
    }
    const metrics::CommandedTrajectory& c = *pending.commanded;
    return first_ps - c.sync_window_ps - c.scan_step_ps;
}

metrics::CommandedTrajectory commanded_trajectory(std::shared_ptr<const host::planner::Trajectory> traj,
                                                  const host::servo::TrajectoryClock& clock, geom::Vec2 origin_mm,
                                                  TimePs scan_step_ps) {
    return commanded_on(
        std::move(traj), [copy = clock](TimePs t) { return copy.at(t); }, clock, origin_mm, scan_step_ps);
}

metrics::CommandedTrajectory commanded_trajectory_live(std::shared_ptr<const host::planner::Trajectory> traj,
                                                       const host::servo::TrajectoryClock& clock, geom::Vec2 origin_mm,
                                                       TimePs scan_step_ps) {
    return commanded_on(
        std::move(traj), [&clock](TimePs t) { return clock.at(t); }, clock, origin_mm, scan_step_ps);
}

void commanded_known(metrics::CommandedTrajectory& c, const host::servo::TrajectoryClock& clock) {
    c.t_begin_ps = clock.t_begin_ps();
    c.t_end_ps = clock.t_end_ps();
}

metrics::CommandedTrajectory commanded_as_planned(std::shared_ptr<const host::planner::Trajectory> traj,
                                                  const host::servo::TrajectoryClock& clock, geom::Vec2 origin_mm,
                                                  TimePs scan_step_ps) {
    const ClockAt as_planned = [](TimePs t) { return host::servo::TrajectoryClock::Reading{ps_to_s(t), 1.0}; };
    return commanded_on(std::move(traj), as_planned, clock, origin_mm, scan_step_ps);
}

}  // namespace cnc::sim
