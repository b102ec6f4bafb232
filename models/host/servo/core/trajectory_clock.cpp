#include "host/servo/core/trajectory_clock.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

namespace cnc::host::servo {

void TrajectoryClock::add(TimePs t_ps, double tau_s) {
    if (!m_t.empty() && (t_ps < m_t.back() || tau_s < m_tau.back())) {
        throw std::logic_error("TrajectoryClock: knots must not go back in time");
    }
    if (m_t.empty()) m_t_first_ps = t_ps;  // drop_before always keeps a knot
    m_t.push_back(t_ps);
    m_tau.push_back(tau_s);
}

void TrajectoryClock::drop_before(TimePs t_ps, double tau_s) {
    const auto by_t = std::upper_bound(m_t.begin(), m_t.end(), t_ps) - m_t.begin();
    const auto by_tau = std::upper_bound(m_tau.begin(), m_tau.end(), tau_s) - m_tau.begin();
    const std::ptrdiff_t keep_from = std::min(by_t, by_tau) - 1;  // the last knot at or before both
    if (keep_from <= 0) return;
    // Erased at the front, the vectors keep their capacity: the knots held stay bounded by the most ever held.
    m_t.erase(m_t.begin(), m_t.begin() + keep_from);
    m_tau.erase(m_tau.begin(), m_tau.begin() + keep_from);
}

TrajectoryClock::Reading TrajectoryClock::at(TimePs t_ps) const {
    if (m_t.empty()) return {};
    if (t_ps < m_t.front()) return {m_tau.front(), 0.0};
    if (t_ps >= m_t.back()) return {m_tau.back(), 0.0};
    const auto it = std::upper_bound(m_t.begin(), m_t.end(), t_ps);
    const auto i = static_cast<std::size_t>(std::distance(m_t.begin(), it)) - 1;
    const double rate = (m_tau[i + 1] - m_tau[i]) / ps_to_s(m_t[i + 1] - m_t[i]);
    return {m_tau[i] + rate * ps_to_s(t_ps - m_t[i]), rate};
}

TimePs TrajectoryClock::depart_time(double tau_s) const {
    if (m_t.empty()) return 0;
    const auto it = std::upper_bound(m_tau.begin(), m_tau.end(), tau_s);  // first knot past tau
    if (it == m_tau.begin()) return m_t.front();
    if (it == m_tau.end()) return m_t.back();
    const auto i = static_cast<std::size_t>(std::distance(m_tau.begin(), it)) - 1;
    const double f = (tau_s - m_tau[i]) / (m_tau[i + 1] - m_tau[i]);
    return m_t[i] + static_cast<TimePs>(std::llround(f * static_cast<double>(m_t[i + 1] - m_t[i])));
}

}  // namespace cnc::host::servo
