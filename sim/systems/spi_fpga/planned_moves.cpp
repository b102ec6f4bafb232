#include "systems/spi_fpga/planned_moves.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <utility>

namespace cnc::sim {

namespace {

constexpr double kSecondsPerMinute = 60.0;
constexpr TimePs kEndOfTime = std::numeric_limits<TimePs>::max();

// The programmed point on the step grid (what the host lands on).
geom::Vec2 on_grid(const host::servo::ServoCore& servo, geom::Vec2 p, std::array<std::int64_t, 2>& steps) {
    const std::array<double, 2> s = servo.position_steps(p);
    const host::servo::ServoConfig& c = servo.config();
    steps = {std::llround(s[0]), std::llround(s[1])};
    return c.origin_mm + geom::Vec2{static_cast<double>(steps[0]) / c.axes[0].steps_per_mm,
                                    static_cast<double>(steps[1]) / c.axes[1].steps_per_mm};
}

using ClockAt = std::function<host::servo::TrajectoryClock::Reading(TimePs)>;

metrics::CommandedTrajectory commanded_on(std::shared_ptr<const host::planner::Trajectory> traj, ClockAt clock_at,
                                          const host::servo::ServoCore& servo) {
    metrics::CommandedTrajectory c;
    commanded_known(c, servo);
    c.origin_mm = servo.config().origin_mm;
    c.scan_step_ps = servo.config().period_ps;  // tau is linear within a period: axis velocities turn at most once
    c.state_at = [traj, clock_at = std::move(clock_at)](TimePs t) {
        const host::servo::TrajectoryClock::Reading r = clock_at(t);
        const host::planner::Sample s = traj->at(r.tau_s);
        return metrics::CommandedState{s.pos_mm, s.vel_mm_per_s * r.rate};
    };
    return c;
}

}  // namespace

std::vector<metrics::MoveSpec> PlannedMoves::take(const host::servo::ServoCore& servo, bool ended) {
    const host::servo::TrajectoryClock& clock = servo.clock();
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
        std::array<std::int64_t, 2> from{};
        std::array<std::int64_t, 2> to{};
        m.from_mm = on_grid(servo, pm.path.start, from);
        m.to_mm = on_grid(servo, pm.path.end, to);
        m.steps = {to[0] - from[0], to[1] - from[1]};
        m.rapid = pm.kind == host::MotionKind::Rapid;
        const double peak = fed->peak_mm_per_s;
        m.feed_mm_per_min = m.rapid && peak > 0.0 ? peak * kSecondsPerMinute : pm.feed_mm_per_min;
        const double length_mm = geom::distance(m.from_mm, m.to_mm);
        if (length_mm > 0.0) {
            const double mm_per_s = m.feed_mm_per_min / kSecondsPerMinute;
            m.rate_steps_per_s = {mm_per_s * static_cast<double>(std::llabs(m.steps[0])) / length_mm,
                                  mm_per_s * static_cast<double>(std::llabs(m.steps[1])) / length_mm};
        }
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
                                                  const host::servo::ServoCore& servo) {
    return commanded_on(std::move(traj), [clock = servo.clock()](TimePs t) { return clock.at(t); }, servo);
}

metrics::CommandedTrajectory commanded_trajectory_live(std::shared_ptr<const host::planner::Trajectory> traj,
                                                       const host::servo::ServoCore& servo) {
    return commanded_on(std::move(traj), [&clock = servo.clock()](TimePs t) { return clock.at(t); }, servo);
}

void commanded_known(metrics::CommandedTrajectory& c, const host::servo::ServoCore& servo) {
    c.t_begin_ps = servo.clock().t_begin_ps();
    c.t_end_ps = servo.clock().t_end_ps();
}

std::vector<std::vector<metrics::RateSegment>> RateSegments::take(fpga::SpiFpgaTop& fpga,
                                                                  const host::servo::ServoCore& servo, bool ended) {
    std::vector<std::vector<metrics::RateSegment>> out(host::servo::kAxes);
    for (std::size_t a = 0; a < host::servo::kAxes; ++a) {
        std::optional<Stretch>& open = m_open[a];
        const auto close = [&] {
            const double mean = open->rate.period_cycles == 0
                                    ? 0.0
                                    : open->requested_sum_steps_per_s / static_cast<double>(open->words);
            out[a].push_back({open->t_ps, mean});
        };
        for (const fpga::AppliedRate& w : fpga.take_applied(a)) {
            // A stretch of one word (the same period and direction reloaded period after period) is one STEP train.
            if (open && !(w.rate == open->rate)) {
                close();
                open.reset();
            }
            if (!open) open = Stretch{w.t_ps, w.rate, 0.0, 0};
            if (w.seq < servo.periods()) {
                open->requested_sum_steps_per_s += std::fabs(servo.record(w.seq).axes[a].requested_steps_per_s);
            }
            ++open->words;
            m_next_seq[a] = w.seq + 1;
        }
        if (ended && open) {
            close();
            open.reset();
        }
    }
    return out;
}

std::uint64_t RateSegments::first_needed_period() const {
    return *std::min_element(m_next_seq.begin(), m_next_seq.end());
}

}  // namespace cnc::sim
