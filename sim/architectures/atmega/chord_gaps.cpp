#include "architectures/atmega/chord_gaps.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cnc::sim {

void ChordGapFold::add_byte(std::size_t transfer, TimePs t_ps) {
    if (!m_last_byte.empty() && m_last_byte.back().first == transfer) {
        m_last_byte.back().second = t_ps;
    } else {
        m_last_byte.emplace_back(transfer, t_ps);
    }
}

TimePs ChordGapFold::arrival(std::size_t transfer) {
    while (!m_last_byte.empty() && m_last_byte.front().first < transfer) m_last_byte.pop_front();
    return !m_last_byte.empty() && m_last_byte.front().first == transfer ? m_last_byte.front().second : -1;
}

// Windows come in plan order, and so do the transfers: the search goes on from the last one found.
std::size_t ChordGapFold::transfer_of(const MotionWindow& w) {
    for (; m_transfer < m_transfers.size(); ++m_transfer) {
        const host::cad2g::Transfer& t = m_transfers[m_transfer];
        if (t.command == w.command && t.motion == static_cast<int>(w.motion)) return m_transfer;
    }
    throw std::logic_error("no transfer carries command " + std::to_string(w.command) + " motion " +
                           std::to_string(w.motion));
}

void ChordGapFold::add_windows(const RecordLog<MotionWindow>& windows, bool ended) {
    for (; m_next_window < windows.size(); ++m_next_window) {
        const MotionWindow& w = windows[m_next_window];
        if (m_prev && w.command == m_prev->command && w.motion != 0) {
            const std::size_t transfer = transfer_of(w);
            const bool later_byte_came = !m_last_byte.empty() && m_last_byte.back().first > transfer;
            if (!ended && !later_byte_came) return;
            const TimePs ready_ps = arrival(transfer);
            if (ready_ps > m_prev->t_end_ps) {
                ++m_gaps.late;
                m_gaps.wait_max_ps = std::max(m_gaps.wait_max_ps, w.t_begin_ps - m_prev->t_end_ps);
                m_gaps.y_steps_waiting += w.y_steps_before_begin - m_prev->y_steps_through_end;
            }
        }
        m_prev = w;
    }
}

}  // namespace cnc::sim
