#include "host/core/host_waits.hpp"

namespace cnc::host {

UnitWaits waits_per_unit(const Program& program, const std::vector<std::size_t>& unit_moves) {
    UnitWaits out;
    out.before_s.assign(unit_moves.size(), 0.0);
    std::size_t next_move = 0;  // waits before moves [next_move, ...) are not laid yet
    for (std::size_t k = 0; k < unit_moves.size(); ++k) {
        if (unit_moves[k] < next_move) continue;  // a later unit of the same move
        out.before_s[k] = program.wait_s_between(next_move, unit_moves[k] + 1);
        next_move = unit_moves[k] + 1;
    }
    out.after_last_s = program.wait_s_between(next_move, program.moves.size() + 1);
    return out;
}

}  // namespace cnc::host
