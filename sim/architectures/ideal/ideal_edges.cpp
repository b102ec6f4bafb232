#include "architectures/ideal/ideal_edges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "metrics/commanded.hpp"

namespace cnc::sim::ideal {

namespace {

constexpr TimePs kEndOfTime = std::numeric_limits<TimePs>::max();

double axis_of(geom::Vec2 v, std::size_t axis) {
    return axis == 0 ? v.x_mm : v.y_mm;
}

Pin step_pin(std::size_t axis) {
    return axis == 0 ? Pin::StepX : Pin::StepY;
}
Pin dir_pin(std::size_t axis) {
    return axis == 0 ? Pin::DirX : Pin::DirY;
}

}  // namespace

IdealEdges::IdealEdges(std::shared_ptr<host::planner::PlanFeed> plan, const StepGrid& grid, TimePs end_ps,
                       TimePs scan_step_ps)
    : m_plan(std::move(plan)), m_grid(grid), m_end_ps(end_ps), m_scan_step_ps(scan_step_ps) {
    m_commanded.state_at = [plan = m_plan](TimePs t_ps) {
        const host::planner::Sample s = plan->at(ps_to_s(t_ps));
        return metrics::CommandedState{s.pos_mm, s.vel_mm_per_s};
    };
    m_commanded.t_begin_ps = 0;
    m_commanded.t_end_ps = end_ps;
    m_commanded.origin_mm = grid.origin_mm;
    m_commanded.scan_step_ps = scan_step_ps;
}

TimePs IdealEdges::next_motion_scan_ps(TimePs t_ps) {
    const double t_s = ps_to_s(t_ps);
    m_plan->plan_past(t_s);
    const std::vector<host::planner::PlannedPiece>& pieces = m_plan->trajectory().pieces();
    const auto moving = std::find_if(pieces.begin(), pieces.end(),
                                     [t_s](const host::planner::PlannedPiece& p) { return p.t_end_s > t_s; });
    // Past the last piece the tool rests to the end; between pieces (a host wait) it rests where the last one left it.
    const TimePs motion_ps = moving == pieces.end() ? m_end_ps : s_to_ps(moving->t_begin_s) - 1;
    if (motion_ps <= t_ps) return t_ps;
    return std::max(t_ps, motion_ps / m_scan_step_ps * m_scan_step_ps);
}

void IdealEdges::add_steps(std::size_t axis, TimePs from_ps, TimePs to_ps) {
    AxisState& st = m_axes[axis];
    const double steps_per_mm = m_grid.steps_per_mm[axis];
    // The scan interval [from, to] alone, on step_crossings' grid from the trajectory's start.
    const metrics::StepCrossings c = metrics::step_crossings(m_commanded, axis, steps_per_mm, from_ps + 1, to_ps - 1);
    std::vector<std::pair<TimePs, int>> steps;
    for (const auto& [n, times] : c.up) {
        for (const TimePs t : times) steps.emplace_back(t, 1);
    }
    for (const auto& [n, times] : c.down) {
        for (const TimePs t : times) steps.emplace_back(t, -1);
    }
    std::sort(steps.begin(), steps.end());
    for (const auto& [t_ps, direction] : steps) {
        const host::planner::Sample s = m_plan->at(ps_to_s(t_ps));
        const double rate = std::fabs(axis_of(s.vel_mm_per_s, axis)) * steps_per_mm;
        const bool constant = axis_of(s.acc_mm_per_s2, axis) == 0.0;
        if (!(constant && st.cruise_rate && *st.cruise_rate == rate)) {
            st.segments.push_back({t_ps, rate});
            st.cruise_rate = constant ? std::optional<double>(rate) : std::nullopt;
        }
        st.train.add(t_ps, direction);
    }
    st.train.advance(to_ps);
    for (const PinEdge& e : st.train.take()) st.edges.push_back(e);
}

void IdealEdges::laser_at(TimePs t_ps, bool on) {
    if (on == m_laser_on) return;
    m_laser_edges.push_back({t_ps, Pin::Laser, on});
    m_laser_on = on;
}

// The laser is on over each programmed move the job wants it in (ProgrammedMove::laser_intended: a cutting move
// under M3/M4 with S > 0), and through the corner blend between two such moves; off in rapids, host waits and after
// the last move. A move is read once the one before has ended within the scan, so that the level is known up to that
// end.
void IdealEdges::add_laser_until(TimePs t_ps) {
    while (!m_previous_move || s_to_ps(m_previous_move->first) <= t_ps) {
        const host::planner::FedMove* fed = m_plan->move(m_next_move);
        if (fed == nullptr) {
            if (m_previous_move) laser_at(s_to_ps(m_previous_move->first), false);
            m_previous_move = {std::numeric_limits<double>::infinity(), false};
            return;
        }
        const auto [begin_s, end_s] = fed->window;
        const bool intended = fed->move.laser_intended();
        if (m_previous_move && begin_s > m_previous_move->first) {
            const host::planner::Sample between = m_plan->at(0.5 * (m_previous_move->first + begin_s));
            const bool blend = between.move < 0 && between.path_speed_mm_per_s > 0.0;
            laser_at(s_to_ps(m_previous_move->first), blend && m_previous_move->second && intended);
        }
        laser_at(s_to_ps(begin_s), intended);
        m_previous_move = {end_s, intended};
        ++m_next_move;
    }
}

void IdealEdges::scan() {
    if (m_scanned_ps >= m_end_ps) {
        for (AxisState& st : m_axes) {
            st.train.finish();
            for (const PinEdge& e : st.train.take()) st.edges.push_back(e);
        }
        add_laser_until(kEndOfTime);
        m_done = true;
        return;
    }
    const TimePs from_ps = next_motion_scan_ps(m_scanned_ps);
    const TimePs to_ps = std::min(from_ps + m_scan_step_ps, m_end_ps);
    for (std::size_t a = 0; a < m_axes.size(); ++a) {
        m_axes[a].train.advance(from_ps);
        add_steps(a, from_ps, to_ps);
    }
    add_laser_until(to_ps);
    m_scanned_ps = to_ps;
}

TimePs IdealEdges::final_until_ps() const {
    if (m_done) return kEndOfTime;
    TimePs until = m_scanned_ps;
    for (const AxisState& st : m_axes) until = std::min(until, st.train.final_until_ps());
    return until;
}

std::optional<TimedEdge> IdealEdges::next() {
    for (;;) {
        // The earliest edge made: X before Y before the laser at one instant.
        std::optional<TimedEdge> first;
        std::deque<PinEdge>* from_axis = nullptr;
        for (std::size_t a = 0; a < m_axes.size(); ++a) {
            std::deque<PinEdge>& edges = m_axes[a].edges;
            if (!edges.empty() && (!first || edges.front().t_ps < first->t_ps)) {
                const PinEdge& e = edges.front();
                first = TimedEdge{e.t_ps, e.step ? step_pin(a) : dir_pin(a), e.level};
                from_axis = &edges;
            }
        }
        const bool laser_first = !m_laser_edges.empty() && (!first || m_laser_edges.front().t_ps < first->t_ps);
        if (laser_first) first = m_laser_edges.front();
        if (first && (m_done || first->t_ps < final_until_ps())) {
            if (laser_first) {
                m_laser_edges.pop_front();
            } else {
                from_axis->pop_front();
            }
            return first;
        }
        if (m_done) return std::nullopt;
        scan();
    }
}

std::vector<std::vector<metrics::RateSegment>> IdealEdges::take_rate_segments(TimePs before_ps) {
    std::vector<std::vector<metrics::RateSegment>> out(m_axes.size());
    for (std::size_t a = 0; a < m_axes.size(); ++a) {
        std::deque<metrics::RateSegment>& segments = m_axes[a].segments;
        for (; !segments.empty() && segments.front().t_ps < before_ps; segments.pop_front()) {
            out[a].push_back(segments.front());
        }
    }
    return out;
}

}  // namespace cnc::sim::ideal
