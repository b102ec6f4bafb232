// The laser bit of each servo frame (bit 30 of the X rate word, models/spi/README.md), from the job's intent per
// programmed move (host::ProgrammedMove::laser_intended: a cutting move under M3/M4 with S > 0; rapids off).
// A frame's rates carry the tool over the stretch of plan the trajectory clock crossed in that period,
// (tau_prev, tau] (the law aims at the command at tau, servo_core.hpp), so the bit is the intent there:
//   - the stretch ends inside a programmed move's piece (a piece boundary counts for the piece ending there, so
//     a rest point belongs to the move that ends at it): that move's intent;
//   - it ends in a corner blend (move -1, the rounded corner between two moves): the previous period's bit if
//     the move after the blend wants the laser too, else off. A blend into a rapid or an M5/S0 move is off: its
//     second half already heads where the job wants no laser, and the commanded trajectory, which the tool follows
//     one period late and by which the metrics time the rapid, enters the rapid as the blend ends;
//   - the clock did not advance (period 0; a hold while the axes land on a rest point) or the stretch ends where
//     no piece runs (a host wait, after the last move): off, the tool is at rest.
// A stretch that crosses a piece boundary takes the piece it ends in (a move shorter than a period may be missed).
#pragma once
#include <cstddef>
#include <vector>

#include "host/core/gcode.hpp"
#include "host/core/planner/plan_feed.hpp"

namespace cnc::host::servo {

// ProgrammedMove::laser_intended of every move, indexed as Program::moves (and planner::PlannedPiece::move).
[[nodiscard]] std::vector<bool> laser_intent(const Program& program);

class LaserBit {
public:
    // `plan` must outlive this; `intended` has one entry per programmed move.
    LaserBit(planner::PlanFeed& plan, std::vector<bool> intended);

    // The bit of the period in which the trajectory clock went from tau_prev_s to tau_s.
    bool next(double tau_prev_s, double tau_s);

private:
    // Whether the first programmed move after the piece at index `blend` wants the laser (a move its two blends
    // consumed has no piece of its own), planning as far as that move.
    [[nodiscard]] bool wanted_after(std::size_t blend);

    planner::PlanFeed& m_plan;
    std::vector<bool> m_intended;
    bool m_on = false;  // the previous period's bit
};

}  // namespace cnc::host::servo
