// Path-speed, path-acceleration and path-jerk limits that keep every axis within its AxisLimits while a curve is
// followed (seed 004 §3.2: limits are per joint; the planner projects them onto the path).
#pragma once
#include "host/core/planner/curve.hpp"
#include "host/core/planner/planner_config.hpp"

namespace cnc::host::planner {

// LinuxCNC tp (blendmath.h): BLEND_ACC_RATIO_NORMAL, the centripetal share of a circle's acceleration budget,
// sqrt(1 - BLEND_ACC_RATIO_TANGENTIAL^2) with the tangential share 0.5. Blends (corner_blend.hpp) use it too.
inline constexpr double kNormalShareCircle = 0.8660254037844386;

struct PathLimits {
    double velocity_mm_per_s;
    double accel_mm_per_s2;  // tangential
    double jerk_mm_per_s3;   // tangential
};

// Lines: each limit is the smallest axis limit divided by that axis' share of the unit tangent (a 45 degree move
// with equal axes may go sqrt(2) times the axis limit along the path).
// Arcs: the tangent turns, so the smaller of the two axis limits is used for the whole arc (exact for any arc
// that passes an axis direction, conservative otherwise), and the acceleration vector is kept inside a circle
// of that radius A: tangential <= A/2 and centripetal v^2/R <= (sqrt(3)/2) A, so |a| <= A (LinuxCNC's
// tp split, BLEND_ACC_RATIO_TANGENTIAL/NORMAL). Hence the arc speed cap sqrt((sqrt(3)/2) A R). A programmed circle
// with a move queued after it (`finalized`, LinuxCNC tc.c tcUpdateCircleAccRatio and blendmath.c
// pmCircleActualMaxVel) whose axis speed limit V needs less centripetal acceleration than that, V^2/R < (sqrt(3)/2) A,
// keeps the rest for the tangent: sqrt(1 - (V^2 / (R A))^2) A. On a spiral the two parts are not orthogonal, so
// each gets A/2 (triangle inequality). The jerk limit is along the path only.
// `feed_mm_per_s` is the programmed speed (infinity: no programmed cap).
PathLimits path_limits(const Curve& curve, double feed_mm_per_s, const PlannerConfig& cfg, bool finalized);

}  // namespace cnc::host::planner
