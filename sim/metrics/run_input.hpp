// What the metrics are computed from: the STEP/DIR edge logs of each axis (as a logic analyser sees
// them), and, for a simulated run, the executed moves, the tool positions and the laser pin (docs/metrics.md).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/edge_log.hpp"
#include "common/geometry.hpp"
#include "common/tool_sample.hpp"
#include "common/units.hpp"
#include "metrics/pulse/driver_timing.hpp"

namespace cnc::metrics {

struct AxisTrace {
    std::string name;           // label in reports ("x", "y"); empty = by position (x, y, z, ...)
    EdgeLog step;               // STEP pin (rising edge = one microstep)
    EdgeLog dir;                // DIR pin
    double steps_per_mm = 0.0;  // 0 = unknown (analyze without --steps-per-mm): mm metrics omitted
    bool dir_high_is_positive = true;
};

using ToolSample = cnc::ToolSample;

// The programmed path and a planner's commanded trajectory are in the XY plane: axes 0 and 1 of RunInput::axes.
inline constexpr std::size_t kPathAxes = 2;

// One executed motion command, a piece of a programmed move (a packet, a chord, a command, or a whole programmed
// move for a planner that follows it as one).
struct MoveSpec {
    int index = 0;
    int line = 0;                  // G-code line
    int programmed = -1;           // the programmed move it executes (index into the job's moves); -1: a piece of its
                                   // own (a steps-file row). Consecutive pieces of one programmed move share it.
    geom::Segment path;            // programmed geometry the move belongs to (a chord's parent arc, or the line)
    geom::Vec2 from_mm, to_mm;     // this move's own commanded end points (chord ends, step-quantised)
    double z_end_mm = 0.0;         // the programmed move's Z at its end (no architecture has Z STEP pins)
    double feed_mm_per_min = 0.0;  // programmed path feed F
    bool rapid = false;            // G0
    // Per axis, in the order of RunInput::axes (an axis with no entry is commanded to stand still):
    std::vector<std::int64_t> steps;       // commanded signed microsteps
    std::vector<double> rate_steps_per_s;  // commanded step rate (what the programmed F implies)
    TimePs t_begin_ps = 0;                 // execution window as the controller reports it (e.g. busy)
    TimePs t_end_ps = 0;
};

// The commanded timed trajectory of a controller with a trajectory planner (docs/metrics.md: sync and following error
// "with a planner"): where the tool should be at each time, as the controller's own clock runs it. With it, following
// error is measured against it and sync error of every STEP edge against the time it crosses that step
// (sync_error.hpp), instead of the uniform motion at F from each move's first step.
struct CommandedState {
    geom::Vec2 pos_mm;
    geom::Vec2 vel_mm_per_s;  // d pos / dt (0 while the trajectory is held)
};

struct CommandedTrajectory {
    // Defined on [t_begin_ps, t_end_ps], continuous in position and velocity; held constant outside.
    std::function<CommandedState(TimePs)> state_at;
    TimePs t_begin_ps = 0;
    TimePs t_end_ps = 0;
    geom::Vec2 origin_mm;  // machine position at step count 0 on every axis (the counts start at 0 at t = 0)
    // Scan step for the step crossings: every axis velocity may change sign at most once between two scan points
    // (a controller that samples its planner once per servo period passes that period).
    TimePs scan_step_ps = kPsPerMs;
    // An edge farther than this from every crossing of its step is one the commanded motion does not make near
    // then (a loop's overshoot and its correction): counted as unmatched instead of a sync error.
    TimePs sync_window_ps = 100 * kPsPerMs;
    // [axis] the step count before the input's first edge, for a window of a run measured as it runs
    // (metrics_stream.hpp); empty: 0, the whole run.
    std::vector<std::int64_t> count_before_steps;
};

// The step rate an axis was commanded from t_ps on (0 = stopped), for a controller that changes rates on its
// own schedule (e.g. a rate word per servo period): pulse runs are then split at every change, not per move.
struct RateSegment {
    TimePs t_ps = 0;
    double steps_per_s = 0.0;
};

struct RunInput {
    std::vector<AxisTrace> axes;   // x, y (analyze may give one)
    std::vector<MoveSpec> moves;   // the executed pieces, sorted by t_begin_ps; empty for analyze
    std::vector<ToolSample> tool;  // sorted by t_ps; empty for analyze
    std::optional<EdgeLog> laser;
    TimePs t_job_start_ps = 0;
    TimePs t_job_end_ps = 0;
    DriverLimits limits;
    double run_split_tolerance = 0.005;                   // analyze only: relative period change that starts a new run
    std::optional<CommandedTrajectory> commanded;         // controllers with a planner
    std::vector<std::vector<RateSegment>> rate_segments;  // [axis], sorted by t_ps; empty: runs per move
};

}  // namespace cnc::metrics
