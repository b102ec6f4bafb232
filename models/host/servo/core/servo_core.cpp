#include "host/servo/core/servo_core.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "host/servo/core/rate_word.hpp"

namespace cnc::host::servo {

namespace {

// A piece that ends below this speed ends at rest (the planner sets stops to exactly 0).
constexpr double kRestSpeedMmPerS = 1e-12;
// The deadband of an axis whose count is exact (count_is_exact): correct any error past half a step, so a stopped
// axis always stands on the step nearest its command (no other step is nearer than that).
constexpr double kStoppedDeadbandSteps = 0.5;

double axis_of(geom::Vec2 v, std::size_t axis) { return axis == 0 ? v.x_mm : v.y_mm; }

}  // namespace

const char* to_string(PeriodMode m) {
    switch (m) {
        case PeriodMode::Track: return "track";
        case PeriodMode::Land: return "land";
        case PeriodMode::Done: return "done";
    }
    return "?";
}

std::vector<double> rest_points(const planner::Trajectory& trajectory) {
    std::vector<double> out;
    for (const planner::PlannedPiece& p : trajectory.pieces()) {
        if (p.speed.exit_mm_per_s <= kRestSpeedMmPerS && (out.empty() || p.t_end_s > out.back())) {
            out.push_back(p.t_end_s);
        }
    }
    if (out.empty() || out.back() < trajectory.duration_s()) out.push_back(trajectory.duration_s());
    return out;
}

ServoCore::ServoCore(const ServoConfig& cfg, const planner::Trajectory& trajectory,
                     std::vector<bool> laser_intended)
    : m_cfg(cfg),
      m_traj(trajectory),
      m_period_s(period_s(cfg)),
      m_land_period_cycles(landing_period_cycles(cfg)),
      m_rest_s(rest_points(trajectory)),
      m_laser(trajectory, std::move(laser_intended)) {
    for (std::size_t a = 0; a < kAxes; ++a) m_params[a] = stepgen_params(cfg, a);
    for (const double r : m_rest_s) {
        const std::array<double, kAxes> p = position_steps(m_traj.at(r).pos_mm);
        m_targets.push_back({std::llround(p[0]), std::llround(p[1])});
    }
    m_stats.rest_points = m_rest_s.size();
    const std::array<double, kAxes> start = position_steps(m_traj.at(0.0).pos_mm);
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
    if (m_landing) {
        if (!land(rec)) return finish(rec);
        ++m_stats.rest_points_landed;
        if (m_rest_index + 1 == m_rest_s.size()) {
            m_done = true;
            rec.mode = PeriodMode::Done;
            return finish(rec);
        }
        ++m_rest_index;
        m_landing = false;
        const std::array<double, kAxes> at = position_steps(m_traj.at(m_tau_s).pos_mm);
        for (std::size_t a = 0; a < kAxes; ++a) m_law[a] = StepgenState{at[a], 0.0};
    }
    const double tau_prev = m_tau_s;
    if (rec.n > 0) m_tau_s = std::min(m_tau_s + m_period_s, m_rest_s[m_rest_index]);
    track(rec);
    rec.laser_on = m_laser.next(tau_prev, m_tau_s);
    if (m_tau_s >= m_rest_s[m_rest_index]) m_landing = true;
    return finish(rec);
}

void ServoCore::track(PeriodRecord& rec) {
    rec.mode = PeriodMode::Track;
    const planner::Sample s = m_traj.at(m_tau_s);
    rec.path_speed_mm_per_s = s.path_speed_mm_per_s;
    const std::array<double, kAxes> cmd = position_steps(s.pos_mm);
    for (std::size_t a = 0; a < kAxes; ++a) {
        const double pos_fb =
            static_cast<double>(m_count[a]) + signed_rate(m_word_prev[a], m_cfg.clk_hz) * m_period_s;
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
    const std::array<std::int64_t, kAxes>& target = m_targets[m_rest_index];
    bool all_landed = true;
    for (std::size_t a = 0; a < kAxes; ++a) {
        AxisPeriod& ap = rec.axes[a];
        ap.pos_cmd_steps = position_steps(m_traj.at(m_tau_s).pos_mm)[a];
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
