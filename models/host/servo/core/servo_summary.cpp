#include "host/servo/core/servo_summary.hpp"

#include <algorithm>

namespace cnc::host::servo {

void ServoSummary::add(const PeriodRecord& rec, const Wakeup& wakeup) {
    if (m_periods == 0) {
        m_latency_min_ps = wakeup.latency_ps;
        m_latency_max_ps = wakeup.latency_ps;
    }
    ++m_periods;
    m_tracking += rec.mode == PeriodMode::Track ? 1 : 0;
    m_landing += rec.mode == PeriodMode::Land ? 1 : 0;
    m_latency_min_ps = std::min(m_latency_min_ps, wakeup.latency_ps);
    m_latency_max_ps = std::max(m_latency_max_ps, wakeup.latency_ps);
    m_latency_sum_ps += static_cast<long double>(wakeup.latency_ps);

    const bool running =
        std::any_of(rec.axes.begin(), rec.axes.end(), [](const AxisPeriod& a) { return a.word.period_cycles != 0; });
    if ((running || !m_staircase.empty()) && m_staircase.size() < kStaircaseRows) {
        StaircaseRow row{wakeup.t_ps, {}, {}};
        for (std::size_t a = 0; a < kAxes; ++a) {
            row.requested_steps_per_s[a] = rec.axes[a].requested_steps_per_s;
            row.word[a] = rec.axes[a].word;
        }
        m_staircase.push_back(row);
    }
}

double ServoSummary::latency_mean_ps() const {
    return m_periods == 0 ? 0.0 : static_cast<double>(m_latency_sum_ps / static_cast<long double>(m_periods));
}

}  // namespace cnc::host::servo
