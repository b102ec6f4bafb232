#include "host/core/host_waits.hpp"

namespace cnc::host {

double UnitWaitLayer::take_before(std::size_t end_move) {
    double s = 0.0;
    for (; m_next_wait < m_waits.size() && m_waits[m_next_wait].before_move < end_move; ++m_next_wait) {
        s += m_waits[m_next_wait].seconds;
    }
    return s;
}

double UnitWaitLayer::before_unit(std::size_t move) {
    if (move < m_next_move) return 0.0;  // a later unit of the same move
    m_next_move = move + 1;
    return take_before(m_next_move);
}

double UnitWaitLayer::after_last() {
    return take_before(static_cast<std::size_t>(-1));
}

UnitWaits waits_per_unit(const Program& program, const std::vector<std::size_t>& unit_moves) {
    UnitWaitLayer layer(program.waits);
    UnitWaits out;
    out.before_s.reserve(unit_moves.size());
    for (const std::size_t move : unit_moves) out.before_s.push_back(layer.before_unit(move));
    out.after_last_s = layer.after_last();
    return out;
}

}  // namespace cnc::host
