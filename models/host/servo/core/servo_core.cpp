#include "host/servo/core/servo_core.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "host/servo/core/rate_word.hpp"

namespace cnc::host::servo {

namespace {

// A piece that ends below this speed ends at rest (the planner sets stops to exactly 0).
constexpr double kRestSpeedMmPerS = 1e-12;
// The deadband of an axis whose count is exact (count_is_exact): correct any error past half a step, so a stopped
// axis always stands on the step nearest its command (no other step is nearer than that).
constexpr double kStoppedDeadbandSteps = 0.5;

double axis_of(geom::Vec2 v, std::size_t axis) {
    return axis == 0 ? v.x_mm : v.y_mm;
}

}  // namespace

const char* to_string(PeriodMode m) {
    switch (m) {
        case PeriodMode::Track:
            return "track";
        case PeriodMode::Land:
            return "land";
        case PeriodMode::Done:
            return "done";
    }
    return "?";
}

std::optional<double> next_rest_point(planner::PlanFeed& plan, std::optional<double> after_s, double until_s) {
    plan.plan_past(until_s);
    const std::vector<planner::PlannedPiece>& pieces = plan.trajectory().pieces();
    const auto later = [&](double t_s) { return !after_s || t_s > *after_s; };
    auto it = pieces.begin();
    if (after_s) {
        it = std::partition_point(pieces.begin(), pieces.end(),
                                  [&](const planner::PlannedPiece& p) { return !later(p.t_end_s); });
    }
    for (; it != pieces.end() && !(it->t_end_s > until_s); ++it) {
        if (it->speed.exit_mm_per_s <= kRestSpeedMmPerS) return it->t_end_s;
    }
    // The plan's end is one too when the host waits after the last piece (planned whole: no piece ends after it).
    if (it == pieces.end() && plan.complete()) {
        const double end_s = plan.trajectory().duration_s();
        if (later(end_s) && !(end_s > until_s)) return end_s;
    }
    return std::nullopt;
}

bool last_rest_point(planner::PlanFeed& plan, double rest_s) {
    plan.plan_past(rest_s);
    return plan.complete() && !(rest_s < plan.trajectory().duration_s());
}

std::uint64_t count_rest_points(planner::PlanFeed& plan) {
    std::uint64_t n = 0;
    std::optional<double> after_s;
    // The horizon runs to the end of what is planned: the pieces behind it have been searched and go.
    for (double until_s = 0.0;;) {
        if (const std::optional<double> r = next_rest_point(plan, after_s, until_s)) {
            ++n;
            after_s = r;
            continue;
        }
        const double planned_s =
            plan.complete() ? plan.trajectory().duration_s() : plan.trajectory().pieces().back().t_end_s;
        if (!(until_s < planned_s)) return n;
        plan.drop_before(until_s);
        plan.drop_moves_before(std::numeric_limits<std::size_t>::max());
        until_s = planned_s;
    }
}

ServoCore::ServoCore(const ServoConfig& cfg, planner::PlanFeed& plan, ServoJob job)
    : m_cfg(cfg),
      m_plan(plan),
      m_period_s(period_s(cfg)),
      m_land_period_cycles(landing_period_cycles(cfg)),
      m_laser(plan, std::move(job.laser_intended)) {
    for (std::size_t a = 0; a < kAxes; ++a) m_params[a] = stepgen_params(cfg, a);
    m_stats.rest_points = job.rest_points;
    const std::array<double, kAxes> start = position_steps(m_plan.at(0.0).pos_mm);
    for (std::size_t a = 0; a < kAxes; ++a) m_law[a].old_pos_cmd_steps = start[a];
}

std::array<double, kAxes> ServoCore::position_steps(geom::Vec2 pos_mm) const {
    std::array<double, kAxes> out{};
    for (std::size_t a = 0; a < kAxes; ++a) {
        out[a] = (axis_of(pos_mm, a) - axis_of(m_cfg.origin_mm, a)) * m_cfg.axes[a].steps_per_mm;
    }
    return out;
}

void ServoCore::drop_log_before(std::uint64_t n) {
    // Erased at the front, the vector keeps its capacity: the records held stay bounded by the most ever held.
    const std::uint64_t k = std::min<std::uint64_t>(n > m_log_first ? n - m_log_first : 0, m_log.size());
    m_log.erase(m_log.begin(), m_log.begin() + static_cast<std::ptrdiff_t>(k));
    m_log_first += k;
}

const PeriodRecord& ServoCore::step(const std::optional<spi::Feedback>& feedback) {
    PeriodRecord rec;
    rec.n = static_cast<std::int64_t>(periods());
    if (feedback) {
        for (std::size_t a = 0; a < kAxes; ++a) m_count[a] = spi::widen_count(m_count[a], feedback->counts[a]);
        m_fifo_level = feedback->status.fifo_level;
        m_have_feedback = true;
        if (feedback->status.dropped) ++m_stats.replies_dropped_flag;
        if (feedback->status.rejected) ++m_stats.replies_rejected_flag;
    }
    rec.fifo_level = m_fifo_level;
    if (m_done) {
        rec.mode = PeriodMode::Done;
        return finish(rec);
    }
    if (m_rest_s) {
        if (!land(rec)) return finish(rec);
        ++m_stats.rest_points_landed;
        if (last_rest_point(m_plan, *m_rest_s)) {
            m_done = true;
            rec.mode = PeriodMode::Done;
            return finish(rec);
        }
        m_rest_s.reset();
        const std::array<double, kAxes> at = position_steps(m_plan.at(m_tau_s).pos_mm);
        for (std::size_t a = 0; a < kAxes; ++a) m_law[a] = StepgenState{at[a], 0.0};
    }
    // The clock runs a period on (not in period 0), up to the next rest point: the first after tau, which is
    // past the last one landed on (tau never passes a rest point).
    const double tau_prev = m_tau_s;
    const double tau_next = rec.n > 0 ? m_tau_s + m_period_s : m_tau_s;
    m_rest_s = next_rest_point(m_plan, rec.n > 0 ? std::optional<double>(m_tau_s) : std::nullopt, tau_next);
    if (m_rest_s) {
        const std::array<double, kAxes> p = position_steps(m_plan.at(*m_rest_s).pos_mm);
        m_target = {std::llround(p[0]), std::llround(p[1])};
    }
    if (rec.n > 0) m_tau_s = m_rest_s ? std::min(tau_next, *m_rest_s) : tau_next;
    track(rec);
    rec.laser_on = m_laser.next(tau_prev, m_tau_s);
    return finish(rec);
}

void ServoCore::track(PeriodRecord& rec) {
    rec.mode = PeriodMode::Track;
    const planner::Sample s = m_plan.at(m_tau_s);
    rec.path_speed_mm_per_s = s.path_speed_mm_per_s;
    const std::array<double, kAxes> cmd = position_steps(s.pos_mm);
    for (std::size_t a = 0; a < kAxes; ++a) {
        const double pos_fb = static_cast<double>(m_count[a]) + signed_rate(m_word_prev[a], m_cfg.clk_hz) * m_period_s;
        StepgenParams params = m_params[a];
        if (count_is_exact(a)) params.deadband_steps = kStoppedDeadbandSteps;
        const StepgenOutput out = stepgen_velocity(params, m_law[a], cmd[a], pos_fb, m_period_s);
        AxisPeriod& ap = rec.axes[a];
        ap.pos_cmd_steps = cmd[a];
        ap.requested_steps_per_s = out.velocity_steps_per_s;
        ap.in_deadband = out.in_deadband;
        ap.word = rate_word_for(out.velocity_steps_per_s, m_cfg.clk_hz, m_cfg.min_period_cycles, m_word_prev[a]);
        m_law[a].vel_fb_steps_per_s = signed_rate(ap.word, m_cfg.clk_hz);
    }
}

bool ServoCore::count_is_exact(std::size_t axis) const {
    return m_have_feedback && m_fifo_level == 0 && !is_running(m_word_prev[axis]) && !is_running(m_word_prev2[axis]);
}

bool ServoCore::land(PeriodRecord& rec) {
    rec.mode = PeriodMode::Land;
    rec.laser_on = m_laser.next(m_tau_s, m_tau_s);  // the clock is held: off
    const std::array<std::int64_t, kAxes>& target = m_target;
    bool all_landed = true;
    for (std::size_t a = 0; a < kAxes; ++a) {
        AxisPeriod& ap = rec.axes[a];
        ap.pos_cmd_steps = position_steps(m_plan.at(m_tau_s).pos_mm)[a];
        ap.word = spi::AxisRate{0, true};
        const bool settled = count_is_exact(a);
        const std::int64_t d = target[a] - m_count[a];
        if (settled && d == 0) continue;
        all_landed = false;
        if (!settled) continue;
        ap.word = spi::AxisRate{m_land_period_cycles, d > 0};
        ap.requested_steps_per_s = signed_rate(ap.word, m_cfg.clk_hz);
        ++m_stats.landing_pulses;
    }
    return all_landed;
}

const PeriodRecord& ServoCore::finish(PeriodRecord& rec) {
    rec.tau_s = m_tau_s;
    for (std::size_t a = 0; a < kAxes; ++a) {
        rec.axes[a].count = m_count[a];
        m_word_prev2[a] = m_word_prev[a];
        m_word_prev[a] = rec.axes[a].word;
    }
    m_clock.add(rec.n * m_cfg.period_ps, m_tau_s);
    m_log.push_back(rec);
    return m_log.back();
}

}  // namespace cnc::host::servo
