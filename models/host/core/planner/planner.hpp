// Trajectory planner over the shared G-code interpreter (seed 004 §3.2-3.3): the host-side path
// planner of the spi-fpga architecture. Seed 004's host is Machinekit, whose planner is LinuxCNC's: the rules
// below follow LinuxCNC 2.9's (src/emc/tp/tp.c, tc.c, blendmath.c; each at the code that applies it). Per-axis
// velocity/acceleration(/jerk) limits, trapezoidal or jerk-limited speed profiles (speed_profile.hpp), exact stop
// (G61.1), exact path (G61) or continuous motion with look-ahead and corner blends within a path tolerance (G64 P).
// Arcs are followed as arcs: every sample lies on the programmed circle (curve.hpp: an arc whose end is off its
// start circle becomes a spiral between the two circles).
//
// Rules (details at each part):
// - Path speed of a move: its feed (mm/min -> mm/s; G0: the interpreter's rapid feed, the machine's rapid speed),
//   capped so that no axis exceeds its limits (path_limits.hpp: tangent projection on lines; smaller axis and
//   tangential A/2 + centripetal (sqrt(3)/2) A on arcs, i.e. arc speed <= sqrt(0.866 A R)).
// - ExactStop (G61.1): every move is its own piece from rest to rest (trapezoid, or triangle when too short).
// - Otherwise, at each junction of the tangent directions u1 -> u2: a change between rapid and feed motion: stop;
//   |u1 x u2| <= 1e-9 and u1.u2 > 0 (same direction, lines or tangent arcs): crossed at the lower of both speed
//   limits, no slowdown otherwise; |u1 x u2| <= 1e-9 and u1.u2 < 0 (reversal): stop; any other corner: a stop in
//   ExactPath (G61), in Continuous (G64) a circular blend (corner_blend.hpp) within the tolerance and a quarter of
//   each move's length replaces the corner region, or a stop when no blend fits. The path leaves the programmed
//   moves only inside blends. A blend's speed limit is the higher of both moves' feeds and its own arc limits.
// - The last move before a rest that is not a stop of its own (the program's end, a host wait) runs at half the
//   acceleration in Continuous mode (LinuxCNC: its end condition is still a parabolic blend).
// - Look-ahead (lookahead.hpp): while a piece runs, the machine must be able to stop at the end of the
//   lookahead_moves programmed moves starting with its own: backward pass per piece over that window, forward
//   pass with the acceleration limit; O(pieces * window). The plan of a piece therefore needs the program only up
//   to the end of its window: plan_stream.hpp plans a job a move at a time, of which plan() is the whole-program case,
//   and plan_feed.hpp reads and plans it only as far as its readers ask.
// - Moves shorter than 1e-9 mm are skipped.
#pragma once
#include "host/core/gcode.hpp"
#include "host/core/planner/planner_config.hpp"
#include "host/core/planner/trajectory.hpp"

namespace cnc::host::planner {

// BadInput for an invalid configuration (validate(cfg, "planner")) or a cutting move without a positive feed.
Trajectory plan(const Program& program, const PlannerConfig& cfg);

}  // namespace cnc::host::planner
