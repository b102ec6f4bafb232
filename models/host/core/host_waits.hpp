// The program's host waits (dwells, operator pauses, Z moves) laid onto what a host sends: each architecture's
// host sends its moves as units (fpga-uart packets, atmega transfers) and waits, before the first unit of a
// move, for every wait programmed before that move; what is programmed after the last move comes at the end.
#pragma once
#include <vector>

#include "host/core/gcode.hpp"

namespace cnc::host {

struct UnitWaits {
    std::vector<double> before_s;  // one per unit
    double after_last_s = 0.0;
};

// `unit_moves[k]` is the programmed move unit k belongs to, in non-decreasing order; a unit that belongs to no
// move (an end-of-program command) has the move index moves.size(). Moves with no unit (too short to step)
// pass their waits on to the next unit.
UnitWaits waits_per_unit(const Program& program, const std::vector<std::size_t>& unit_moves);

}  // namespace cnc::host
