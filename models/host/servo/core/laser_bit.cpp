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

LaserBit::LaserBit(planner::PlanFeed& plan, std::vector<bool> intended)
    : m_plan(plan), m_intended(std::move(intended)) {}

bool LaserBit::next(double tau_prev_s, double tau_s) {
    if (!(tau_s > tau_prev_s)) return m_on = false;
    m_plan.plan_past(tau_s);
    const std::vector<planner::PlannedPiece>& pieces = m_plan.trajectory().pieces();
    // The first piece ending at or after tau: the stretch ends in it unless it only begins at or after tau.
    const auto it = std::lower_bound(pieces.begin(), pieces.end(), tau_s,
                                     [](const planner::PlannedPiece& p, double t) { return p.t_end_s < t; });
    if (it == pieces.end() || it->t_begin_s >= tau_s) return m_on = false;
    if (it->move < 0) return m_on = m_on && wanted_after(static_cast<std::size_t>(it - pieces.begin()));
    return m_on = m_intended.at(static_cast<std::size_t>(it->move));
}

bool LaserBit::wanted_after(std::size_t blend) {
    // Indices, not iterators: planning more appends to the pieces.
    const std::vector<planner::PlannedPiece>& pieces = m_plan.trajectory().pieces();
    for (std::size_t i = blend;; ++i) {
        while (i == pieces.size()) {
            if (!m_plan.plan_next()) return false;
        }
        if (pieces[i].move >= 0) return m_intended.at(static_cast<std::size_t>(pieces[i].move));
    }
}

}  // namespace cnc::host::servo
