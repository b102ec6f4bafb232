// Trajectory planner settings (seed 004 §3.2-3.3: per-axis limits, trapezoidal or cubic-acceleration profiles,
// point-to-point or continuous planning with a bounded corner deviation, LinuxCNC G61 / G61.1 / G64 P).
#pragma once
#include <string>

#include "host/core/machine.hpp"

namespace cnc::host::planner {

// The machine's axis limits (machine.hpp): the planner honours all three.
using AxisLimits = host::AxisLimits;

// seed 004 §3.2 (figs. 3.2, 3.3): trapezoidal = constant-acceleration phases; JerkLimited = the "cubic
// acceleration" profile (acceleration a smooth polynomial, jerk bounded).
enum class Profile { Trapezoidal, JerkLimited };

// LinuxCNC's path control modes (G-code reference, "G61, G61.1 Exact Path, Exact Stop", "G64 Path Blending").
enum class BlendMode {
    ExactStop,   // G61.1: every programmed move starts and ends at rest (seed 004 §3.2 "point-to-point")
    ExactPath,   // G61: the programmed path exactly, a stop at every corner, tangent joins crossed at speed
    Continuous,  // G64 P: corners rounded by arcs at most path_tolerance_mm from the corner (seed 004 §3.2)
};

struct PlannerConfig {
    AxisLimits x, y;
    Profile profile = Profile::Trapezoidal;
    BlendMode mode = BlendMode::Continuous;
    double path_tolerance_mm = 0.05;  // G64 P while the program sets none; 0 makes every non-tangent corner a stop
    int lookahead_moves = 32;         // programmed moves the planner sees ahead (the window must end at rest)
};

// BadInput(where, "<field> must be ...") for a velocity, acceleration or jerk <= 0 (or not finite), a negative
// tolerance, or a look-ahead below 1.
void validate(const PlannerConfig& cfg, const std::string& where);

}  // namespace cnc::host::planner
