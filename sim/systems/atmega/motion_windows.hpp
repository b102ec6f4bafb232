// When each seed 003 motion (a G00, a G01, one arc chord) ran, read back from the PORTB pins: every start byte
// the firmware writes changes at least one of EN_X, EN_Y, DIR_X, DIR_Y, HEADER at one instant (a single OUT),
// and nothing else changes them except the end of a count (App. A2-A4):
//   * a command starts when an EN pin goes low after both were high, and a G00/G01 ends when both are high;
//   * a chord ends when the Timer0 ISR has counted X to zero, which raises EN_X alone, and the next chord starts
//     at the next PORTB change that is not EN_X rising alone (the reload: EN_X falls, or, for a chord with
//     dx = 0, DIR_X flips, which the PC program guarantees for exactly that purpose: plan.hpp);
//   * a chord whose X was disabled (dx = 0) ends where the next one starts; the last chord of an arc ends at its
//     ISR, or where both EN pins are high.
// Y steps between a chord's end and the next reload (late data: seed 003 §5.4.3 "the motion continues") belong
// to the chord that ended.
#pragma once
#include <vector>

#include "common/edge_log.hpp"
#include "host/core/seed003/plan.hpp"

namespace cnc::sim {

struct PortbLines {
    const EdgeLog& en_x;
    const EdgeLog& en_y;
    const EdgeLog& dir_x;
    const EdgeLog& dir_y;
    const EdgeLog& head;
};

struct MotionWindow {
    std::size_t command = 0;  // index into Plan::commands
    std::size_t motion = 0;   // index into the command's motions
    TimePs t_begin_ps = 0;    // the start byte (or chord reload) was written
    TimePs t_end_ps = 0;      // the count ended (t_sim_end_ps when the run stopped first)
    bool complete = true;     // false: the run stopped before the motion ended
};

// Windows of the motions that started, in plan order. `t_sim_end_ps` closes a motion the run did not finish.
[[nodiscard]] std::vector<MotionWindow> motion_windows(const host::seed003::Plan& plan, const PortbLines& lines,
                                                       TimePs t_sim_end_ps);

}  // namespace cnc::sim
