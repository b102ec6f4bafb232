#include "host/core/planner/lookahead.hpp"

#include <algorithm>
#include <cstddef>

#include "host/core/planner/speed_profile.hpp"

namespace cnc::host::planner {

std::vector<double> boundary_speeds(const std::vector<LookaheadPiece>& pieces, Profile shape, int lookahead_moves) {
    Lookahead look(shape, lookahead_moves);
    for (const LookaheadPiece& p : pieces) look.add(p);
    std::vector<double> speeds{0.0};
    while (const std::optional<double> exit = look.next_exit(true)) speeds.push_back(*exit);
    return speeds;
}

std::optional<double> Lookahead::next_exit(bool ended) {
    if (m_pieces.empty()) return std::nullopt;
    const LookaheadPiece& piece = m_pieces.front();
    const long long last_visible = static_cast<long long>(piece.last_move_needed) + m_lookahead_moves - 1;
    m_window_end = std::max<std::size_t>(m_window_end, 1);
    while (m_window_end < m_pieces.size() && m_pieces[m_window_end].last_move_needed <= last_visible) ++m_window_end;
    // A later piece may still join the window.
    if (m_window_end == m_pieces.size() && !ended) return std::nullopt;
    // Backward from rest at the window's end to the end of the piece.
    double exit_cap = 0.0;
    for (std::size_t j = m_window_end; --j > 0;) {
        exit_cap = std::min(m_pieces[j].entry_cap_mm_per_s,
                            reachable_speed(m_shape, exit_cap, m_pieces[j].length_mm, m_pieces[j].limits));
    }
    const double exit = std::min(exit_cap, reachable_speed(m_shape, m_entry_mm_per_s, piece.length_mm, piece.limits));
    m_pieces.pop_front();
    --m_window_end;
    m_entry_mm_per_s = exit;
    return exit;
}

}  // namespace cnc::host::planner
