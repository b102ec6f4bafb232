#include "host/servo/core/laser_bit.hpp"

#include <algorithm>
#include <utility>

namespace cnc::host::servo {

std::vector<bool> laser_intent(const Program& program) {
    std::vector<bool> out;
    out.reserve(program.moves.size());
    for (const ProgrammedMove& m : program.moves) out.push_back(m.laser_intended());
    return out;
}

LaserBit::LaserBit(const planner::Trajectory& trajectory, std::vector<bool> intended)
    : m_traj(trajectory), m_intended(std::move(intended)) {}

bool LaserBit::next(double tau_prev_s, double tau_s) {
    if (!(tau_s > tau_prev_s)) return m_on = false;
    const std::vector<planner::PlannedPiece>& pieces = m_traj.pieces();
    // The first piece ending at or after tau: the stretch ends in it unless it only begins at or after tau.
    const auto it = std::lower_bound(pieces.begin(), pieces.end(), tau_s,
                                     [](const planner::PlannedPiece& p, double t) { return p.t_end_s < t; });
    if (it == pieces.end() || it->t_begin_s >= tau_s) return m_on = false;
    if (it->move < 0) return m_on = m_on && wanted_after(it);
    return m_on = m_intended.at(static_cast<std::size_t>(it->move));
}

bool LaserBit::wanted_after(std::vector<planner::PlannedPiece>::const_iterator blend) const {
    const std::vector<planner::PlannedPiece>& pieces = m_traj.pieces();
    const auto next =
        std::find_if(blend, pieces.end(), [](const planner::PlannedPiece& p) { return p.move >= 0; });
    return next != pieces.end() && m_intended.at(static_cast<std::size_t>(next->move));
}

}  // namespace cnc::host::servo
