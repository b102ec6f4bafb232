// Corner rounding for continuous mode (seed 004 §3.2 figs. 3.5-3.6; LinuxCNC G64 P): a circular arc tangent to
// the incoming and the outgoing curve replaces the corner.
#pragma once
#include <optional>

#include "host/core/planner/curve.hpp"

namespace cnc::host::planner {

// The blend arc at the corner a.end == b.start (a and b uncut: each may give at most half of its length). It
// lies on the inside of the turn, is tangent to a at its start and to b at its end, and its distance from the
// corner point is at most tolerance_mm, as large as those rules allow (largest radius = fastest corner).
// Two lines: closed form, radius R = min(tol cos(h) / (1 - cos(h)), min(La, Lb) / 2 / tan(h)), h = half the
// turn angle; the arc starts R tan(h) before the corner, and its midpoint, R (1/cos(h) - 1) from the corner, is
// also its farthest point from the two lines. An arc on either side: the centre is where the curves offset by R
// towards the inside meet (a spiral side is taken as its circle at the corner end, which it follows there); R is
// the largest valid one (bisection), then reduced until 15 samples of the blend lie within tolerance_mm of the
// two curves, so that the contour error, not only the distance to the corner point, stays within the tolerance.
// Of that largest radius R_geom, LinuxCNC 2.9 (blendmath.c blendComputeParameters) takes only what the time it
// would spend in the blend asks for: with a_n = (sqrt(3)/2) A the centripetal share of the acceleration A, the
// blend's speed v = min(sqrt(a_n R_geom), v_goal), the time t = min(sqrt(A d_geom), v) / (A/2) and the turn phi,
// R = max(v^2 / a_n, min(t v / phi, R_geom)); the same is done here. `goal_mm_per_s` is the blend's goal speed,
// `accel_mm_per_s2` the acceleration A every direction of the plane has.
// nullopt when no such arc exists (reversal, zero tolerance, arcs too tight): the corner is then a stop.
std::optional<Curve> corner_blend(const Curve& a, const Curve& b, double tolerance_mm, double goal_mm_per_s,
                                  double accel_mm_per_s2);

}  // namespace cnc::host::planner
