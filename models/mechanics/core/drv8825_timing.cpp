#include "mechanics/core/drv8825_timing.hpp"

#include <algorithm>

namespace cnc::mech {

std::int64_t TimingStats::total_violations() const {
    std::int64_t n = 0;
    for (const RuleStats& r : rules) n += r.violations;
    return n;
}

void Drv8825TimingChecker::measure(TimingRule rule, TimePs t_ps, TimePs value_ps, bool violated) {
    RuleStats& r = m_stats.rules[static_cast<std::size_t>(rule)];
    ++r.checks;
    if (violated && r.violations++ == 0) r.first_violation_ps = t_ps;
    r.worst_ps = r.worst_ps ? std::min(*r.worst_ps, value_ps) : value_ps;
}

void Drv8825TimingChecker::on_step(TimePs t_ps, bool level) {
    if (level == m_step) return;
    m_step = level;
    if (!level) {
        if (m_last_rise_ps) {
            const TimePs high = t_ps - *m_last_rise_ps;
            measure(TimingRule::StepHigh, t_ps, high, high < m_limits.step_high_min_ps);
        }
        m_last_fall_ps = t_ps;
        return;
    }
    if (m_last_fall_ps) {
        const TimePs low = t_ps - *m_last_fall_ps;
        measure(TimingRule::StepLow, t_ps, low, low < m_limits.step_low_min_ps);
    }
    if (m_last_dir_change_ps) {
        const TimePs setup = t_ps - *m_last_dir_change_ps;
        measure(TimingRule::DirSetup, t_ps, setup, setup < m_limits.dir_setup_min_ps);
    }
    if (m_last_rise_ps) {
        const TimePs period = t_ps - *m_last_rise_ps;
        const bool too_fast =
            period <= 0 || static_cast<double>(kPsPerSec) / static_cast<double>(period) > m_limits.step_rate_max_hz;
        measure(TimingRule::StepRate, t_ps, period, too_fast);
    }
    m_last_rise_ps = t_ps;
}

void Drv8825TimingChecker::on_dir(TimePs t_ps, bool level) {
    if (level == m_dir) return;
    m_dir = level;
    if (m_last_rise_ps && *m_last_rise_ps == t_ps) {
        measure(TimingRule::DirSetup, t_ps, 0, m_limits.dir_setup_min_ps > 0);
    } else if (m_last_rise_ps) {
        const TimePs hold = t_ps - *m_last_rise_ps;
        measure(TimingRule::DirHold, t_ps, hold, hold < m_limits.dir_hold_min_ps);
    }
    m_last_dir_change_ps = t_ps;
}

}  // namespace cnc::mech
