#include "architectures/grbl/step_windows.hpp"

#include <algorithm>
#include <utility>

namespace cnc::sim {

StepWindowFold::StepWindowFold(std::vector<std::array<std::int64_t, 2>> ends, bool dir_high_is_positive)
    : m_ends(std::move(ends)), m_dir_high_is_positive(dir_high_is_positive) {}

void StepWindowFold::add(const EdgeLog& step_x, const EdgeLog& dir_x, const EdgeLog& step_y, const EdgeLog& dir_y) {
    struct Pulse {
        TimePs t_ps;
        int axis;
        int delta;
    };
    std::vector<Pulse> pulses;
    const EdgeLog* steps[2] = {&step_x, &step_y};
    const EdgeLog* dirs[2] = {&dir_x, &dir_y};
    for (int a = 0; a < 2; ++a) {
        for (const TimePs t : steps[a]->rising()) {
            const bool positive = dirs[a]->level_at(t) == m_dir_high_is_positive;
            pulses.push_back({t, a, positive ? 1 : -1});
        }
    }
    std::stable_sort(pulses.begin(), pulses.end(), [](const Pulse& p, const Pulse& q) { return p.t_ps < q.t_ps; });
    for (const Pulse& p : pulses) {
        m_position[static_cast<std::size_t>(p.axis)] += p.delta;
        if (m_next == m_ends.size()) {
            ++m_steps_after_last;
            continue;
        }
        if (!m_open) {
            m_open = true;
            m_begin_ps = p.t_ps;
        }
        if (m_position == m_ends[m_next]) {
            m_windows.push_back({m_begin_ps, p.t_ps, true});
            m_open = false;
            ++m_next;
        }
    }
}

void StepWindowFold::finish(TimePs t_sim_end_ps) {
    if (!m_open) return;
    m_windows.push_back({m_begin_ps, t_sim_end_ps, false});
    m_open = false;
    ++m_next;
}

}  // namespace cnc::sim
