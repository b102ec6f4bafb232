#include "host/core/planner/trajectory.hpp"

#include <algorithm>
#include <iterator>

namespace cnc::host::planner {

Trajectory::Trajectory(std::vector<PlannedPiece> pieces, std::vector<std::pair<double, double>> move_windows,
                       geom::Vec2 rest_mm, double end_hold_s)
    : m_pieces(std::move(pieces)),
      m_move_windows(std::move(move_windows)),
      m_rest_mm(rest_mm),
      m_end_hold_s(end_hold_s) {}

void Trajectory::append(std::vector<PlannedPiece> pieces, geom::Vec2 rest_mm) {
    m_pieces.insert(m_pieces.end(), std::make_move_iterator(pieces.begin()), std::make_move_iterator(pieces.end()));
    m_rest_mm = rest_mm;
}

void Trajectory::drop_before(double t_s) {
    const auto it = std::upper_bound(m_pieces.begin(), m_pieces.end(), t_s,
                                     [](double time, const PlannedPiece& p) { return time < p.t_begin_s; });
    if (it == m_pieces.begin()) return;
    // Erased at the front, the vector keeps its capacity: the pieces held stay bounded by the most ever held.
    m_pieces.erase(m_pieces.begin(), std::prev(it));
}

Sample Trajectory::at(double t_s) const {
    const double t = std::clamp(t_s, 0.0, duration_s());
    if (m_pieces.empty() || t < m_pieces.front().t_begin_s) return Sample{t, m_rest_mm, {}, {}, 0.0, -1};
    auto it = std::upper_bound(m_pieces.begin(), m_pieces.end(), t,
                               [](double time, const PlannedPiece& p) { return time < p.t_begin_s; });
    const PlannedPiece& piece = *std::prev(it);
    // At the end of the last piece, its own duration (t_end - t_begin can differ from it by an ulp).
    const double local = t >= piece.t_end_s ? piece.speed.duration_s() : t - piece.t_begin_s;
    const PathState st = piece.speed.at(local);
    const geom::Vec2 d1 = piece.path.first_derivative(st.s_mm);
    const geom::Vec2 d2 = piece.path.second_derivative(st.s_mm);
    return Sample{t,
                  piece.path.point_at(st.s_mm),
                  d1 * st.v_mm_per_s,
                  d1 * st.a_mm_per_s2 + d2 * (st.v_mm_per_s * st.v_mm_per_s),
                  st.v_mm_per_s,
                  piece.move};
}

}  // namespace cnc::host::planner
