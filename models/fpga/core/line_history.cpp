#include "fpga/core/line_history.hpp"

#include <algorithm>

namespace cnc::fpga {

void LineHistory::add(TimePs t_ps, bool level) {
    if (level != current_level()) m_changes.push_back({t_ps, level});
}

bool LineHistory::level_before(TimePs t_ps) const {
    const auto it =
        std::lower_bound(m_changes.begin(), m_changes.end(), t_ps, [](const Edge& e, TimePs t) { return e.t_ps < t; });
    return it == m_changes.begin() ? m_level_before : std::prev(it)->level;
}

std::optional<TimePs> LineHistory::first_change_at_or_after(TimePs t_ps) const {
    const auto it =
        std::lower_bound(m_changes.begin(), m_changes.end(), t_ps, [](const Edge& e, TimePs t) { return e.t_ps < t; });
    if (it == m_changes.end()) return std::nullopt;
    return it->t_ps;
}

void LineHistory::forget_before(TimePs t_ps) {
    while (!m_changes.empty() && m_changes.front().t_ps < t_ps) {
        m_level_before = m_changes.front().level;
        m_changes.pop_front();
    }
}

}  // namespace cnc::fpga
