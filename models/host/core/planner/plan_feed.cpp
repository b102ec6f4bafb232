#include "host/core/planner/plan_feed.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace cnc::host::planner {

PlanFeed::PlanFeed(const PlannerConfig& cfg, std::unique_ptr<GcodeStream> moves)
    : m_moves(std::move(moves)), m_stream(cfg, m_moves->program().filename) {}

Sample PlanFeed::at(double t_s) {
    plan_past(t_s);
    return m_traj.at(t_s);
}

void PlanFeed::plan_past(double t_s) {
    while (!m_complete && (m_traj.pieces().empty() || !(m_traj.pieces().back().t_end_s > t_s))) plan_next();
}

bool PlanFeed::plan_next() {
    if (m_complete) return false;
    std::optional<ProgrammedMove> move = m_moves->next();
    // The waits before this move (all that are left after the last): the stream has read them with it.
    const std::vector<HostWait>& waits = m_moves->program().waits;
    for (; m_waits_added < waits.size() && (!move || waits[m_waits_added].before_move <= m_read); ++m_waits_added) {
        m_stream.add_wait(waits[m_waits_added].seconds);
    }
    if (move) {
        m_stream.add_move(*move);
        m_unplanned.push_back(FedMove{std::move(*move), {}, 0.0});
        ++m_read;
    } else {
        m_stream.finish();
        m_traj.set_end_hold(m_stream.end_hold_s());
        m_complete = true;
    }
    take();
    return true;
}

void PlanFeed::take() {
    std::vector<PlannedPiece> pieces = m_stream.take_pieces();
    // A move's own piece is taken with its window (or before it): the move is still waiting for that window.
    const std::size_t first_unplanned = m_first_planned + m_planned.size();
    for (const PlannedPiece& p : pieces) {
        if (p.move < 0) continue;
        double& peak = m_unplanned.at(static_cast<std::size_t>(p.move) - first_unplanned).peak_mm_per_s;
        peak = std::max(peak, p.speed.peak_mm_per_s);
    }
    m_traj.append(std::move(pieces), m_stream.rest_mm());
    for (const std::pair<double, double>& window : m_stream.take_windows()) {
        m_planned.push_back(std::move(m_unplanned.front()));
        m_planned.back().window = window;
        m_unplanned.pop_front();
    }
}

const FedMove* PlanFeed::move(std::size_t i) {
    while (i >= m_first_planned + m_planned.size() && plan_next()) {
    }
    return i < m_first_planned + m_planned.size() ? &m_planned[i - m_first_planned] : nullptr;
}

void PlanFeed::drop_moves_before(std::size_t i) {
    for (; m_first_planned < i && !m_planned.empty(); ++m_first_planned) m_planned.pop_front();
}

}  // namespace cnc::host::planner
