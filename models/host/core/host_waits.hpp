// The program's host waits (dwells, operator pauses, Z moves) laid onto what a host sends: each architecture's
// host sends its moves as units (fpga-uart packets, atmega transfers) and waits, before the first unit of a
// move, for every wait programmed before that move; what is programmed after the last move comes at the end.
#pragma once
#include <cstddef>
#include <vector>

#include "host/core/gcode.hpp"

namespace cnc::host {

struct UnitWaits {
    std::vector<double> before_s;  // one per unit
    double after_last_s = 0.0;
};

// The waits laid one unit at a time, as a streamed job's units are made. `waits` (Program::waits) must outlive it.
class UnitWaitLayer {
public:
    explicit UnitWaitLayer(const std::vector<HostWait>& waits) : m_waits(waits) {}
    // The wait before the next unit, which belongs to programmed move `move` (not below the previous unit's): every
    // wait before that move not laid yet. Moves with no unit (too short to step) pass their waits on.
    [[nodiscard]] double before_unit(std::size_t move);
    // Every wait not laid yet, after the last unit.
    [[nodiscard]] double after_last();

private:
    [[nodiscard]] double take_before(std::size_t end_move);

    const std::vector<HostWait>& m_waits;
    std::size_t m_next_wait = 0;
    std::size_t m_next_move = 0;  // waits before moves [m_next_move, ...) are not laid yet
};

// `unit_moves[k]` is the programmed move unit k belongs to, in non-decreasing order; a unit that belongs to no
// move (an end-of-program command) has the move index moves.size().
UnitWaits waits_per_unit(const Program& program, const std::vector<std::size_t>& unit_moves);

}  // namespace cnc::host
