// Level history of an asynchronous input line (uart_rx's rx pin), so that an event-driven receiver can ask
// after the fact which level a clock edge sampled, exactly as the 2-FF synchroniser would have.
#pragma once
#include <deque>
#include <optional>

#include "common/edge_log.hpp"
#include "common/units.hpp"

namespace cnc::fpga {

class LineHistory {
public:
    explicit LineHistory(bool level_before_history) : m_level_before(level_before_history) {}

    // Appends a change (times non-decreasing); a "change" to the current level is ignored.
    void add(TimePs t_ps, bool level);
    // Level after the last change strictly before t: what a clock edge at t samples.
    [[nodiscard]] bool level_before(TimePs t_ps) const;
    // Time of the first change at or after t, if one has been recorded.
    [[nodiscard]] std::optional<TimePs> first_change_at_or_after(TimePs t_ps) const;
    // Drops changes before t (level_before(t') stays right for every t' >= t).
    void forget_before(TimePs t_ps);
    [[nodiscard]] bool current_level() const { return m_changes.empty() ? m_level_before : m_changes.back().level; }

private:
    bool m_level_before;
    std::deque<Edge> m_changes;
};

}  // namespace cnc::fpga
