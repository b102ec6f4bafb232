// Trajectory planner settings (seed 004 §3.2-3.3: per-axis limits, trapezoidal or cubic-acceleration profiles,
// point-to-point or continuous planning with a bounded corner deviation, LinuxCNC G61 / G64 P).
#pragma once
#include <string>

#include "host/core/machine.hpp"

namespace cnc::host::planner {

// The machine's axis limits (machine.hpp): the planner honours all three.
using AxisLimits = host::AxisLimits;

// seed 004 §3.2 (figs. 3.2, 3.3): trapezoidal = constant-acceleration phases; JerkLimited = the "cubic
// acceleration" profile (acceleration a smooth polynomial, jerk bounded).
enum class Profile { Trapezoidal, JerkLimited };

enum class BlendMode {
    ExactStop,   // G61: every programmed move starts and ends at rest (seed 004 §3.2 "point-to-point")
    Continuous,  // G64 P: corners rounded by arcs at most path_tolerance_mm from the corner (seed 004 §3.2)
};

struct PlannerConfig {
    AxisLimits x, y;
    Profile profile = Profile::Trapezoidal;
    BlendMode mode = BlendMode::Continuous;
    double path_tolerance_mm = 0.05;  // G64 P; 0 makes every non-tangent corner a stop
    int lookahead_moves = 32;         // programmed moves the planner sees ahead (the window must end at rest)
};

// BadInput(where, "<field> must be ...") for a velocity, acceleration or jerk <= 0 (or not finite), a negative
// tolerance, or a look-ahead below 1.
void validate(const PlannerConfig& cfg, const std::string& where);

}  // namespace cnc::host::planner
