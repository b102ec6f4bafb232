#include "systems/spi_fpga/planned_moves.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace cnc::sim {

namespace {

constexpr double kSecondsPerMinute = 60.0;

// The programmed point on the step grid (what the host lands on).
geom::Vec2 on_grid(const host::servo::ServoCore& servo, geom::Vec2 p, std::array<std::int64_t, 2>& steps) {
    const std::array<double, 2> s = servo.position_steps(p);
    const host::servo::ServoConfig& c = servo.config();
    steps = {std::llround(s[0]), std::llround(s[1])};
    return c.origin_mm + geom::Vec2{static_cast<double>(steps[0]) / c.axes[0].steps_per_mm,
                                    static_cast<double>(steps[1]) / c.axes[1].steps_per_mm};
}

double planned_peak_mm_per_s(const host::planner::Trajectory& traj, int move) {
    double peak = 0.0;
    for (const host::planner::PlannedPiece& p : traj.pieces()) {
        if (p.move == move) peak = std::max(peak, p.speed.peak_mm_per_s);
    }
    return peak;
}

}  // namespace

std::vector<metrics::MoveSpec> planned_moves(const host::Program& program, const host::planner::Trajectory& traj,
                                             const host::servo::ServoCore& servo) {
    const host::servo::TrajectoryClock& clock = servo.clock();
    std::vector<metrics::MoveSpec> moves;
    for (std::size_t i = 0; i < program.moves.size(); ++i) {
        const host::ProgrammedMove& pm = program.moves[i];
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
        const double peak = planned_peak_mm_per_s(traj, static_cast<int>(i));
        m.feed_mm_per_min = m.rapid && peak > 0.0 ? peak * kSecondsPerMinute : pm.feed_mm_per_min;
        const double length_mm = geom::distance(m.from_mm, m.to_mm);
        if (length_mm > 0.0) {
            const double mm_per_s = m.feed_mm_per_min / kSecondsPerMinute;
            m.rate_steps_per_s = {mm_per_s * static_cast<double>(std::llabs(m.steps[0])) / length_mm,
                                  mm_per_s * static_cast<double>(std::llabs(m.steps[1])) / length_mm};
        }
        const auto& window = traj.move_windows()[i];
        m.t_begin_ps = clock.depart_time(window.first);
        m.t_end_ps = clock.depart_time(window.second);
        moves.push_back(m);
    }
    return moves;
}

metrics::CommandedTrajectory commanded_trajectory(std::shared_ptr<const host::planner::Trajectory> traj,
                                                  const host::servo::ServoCore& servo) {
    const host::servo::TrajectoryClock clock = servo.clock();
    metrics::CommandedTrajectory c;
    c.t_begin_ps = clock.t_begin_ps();
    c.t_end_ps = clock.t_end_ps();
    c.origin_mm = servo.config().origin_mm;
    c.scan_step_ps = servo.config().period_ps;  // tau is linear within a period: axis velocities turn at most once
    c.state_at = [traj, clock](TimePs t) {
        const host::servo::TrajectoryClock::Reading r = clock.at(t);
        const host::planner::Sample s = traj->at(r.tau_s);
        return metrics::CommandedState{s.pos_mm, s.vel_mm_per_s * r.rate};
    };
    return c;
}

std::vector<std::vector<metrics::RateSegment>> rate_segments(const fpga::SpiFpgaTop& fpga,
                                                             const host::servo::ServoCore& servo) {
    const std::vector<host::servo::PeriodRecord>& log = servo.log();
    std::vector<std::vector<metrics::RateSegment>> out(host::servo::kAxes);
    for (std::size_t a = 0; a < host::servo::kAxes; ++a) {
        const std::vector<fpga::AppliedRate>& applied = fpga.applied(a);
        for (std::size_t k = 0; k < applied.size();) {
            // A stretch of one word (the same period and direction reloaded period after period) is one STEP train.
            std::size_t end = k + 1;
            while (end < applied.size() && applied[end].rate == applied[k].rate) ++end;
            double sum = 0.0;
            for (std::size_t i = k; i < end; ++i) {
                if (applied[i].seq < log.size()) sum += std::fabs(log[applied[i].seq].axes[a].requested_steps_per_s);
            }
            const double mean = applied[k].rate.period_cycles == 0 ? 0.0 : sum / static_cast<double>(end - k);
            out[a].push_back({applied[k].t_ps, mean});
            k = end;
        }
    }
    return out;
}

}  // namespace cnc::sim
