// What the metrics are computed from: the STEP/DIR edge logs of each axis (as a logic analyser sees
// them), and, for a simulated run, the executed moves, the tool positions and the laser pin (DESIGN.md §4).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/edge_log.hpp"
#include "common/geometry.hpp"
#include "common/tool_sample.hpp"
#include "common/units.hpp"
#include "metrics/driver_timing.hpp"

namespace cnc::metrics {

struct AxisTrace {
    std::string name;  // label in reports ("x", "y"); empty = by position (x, y, z, ...)
    EdgeLog step;      // STEP pin (rising edge = one microstep)
    EdgeLog dir;       // DIR pin
    double steps_per_mm = 0.0;  // 0 = unknown (analyze without --steps-per-mm): mm metrics omitted
    bool dir_high_is_positive = true;
};

using ToolSample = cnc::ToolSample;

// One executed motion command (packet, chord or planner segment).
struct MoveSpec {
    int index = 0;
    int line = 0;                 // G-code line
    geom::Segment path;           // programmed geometry the move belongs to (a chord's parent arc, or the line)
    geom::Vec2 from_mm, to_mm;    // this move's own commanded end points (chord ends, step-quantised)
    double feed_mm_per_min = 0.0; // programmed path feed F
    bool rapid = false;           // G0
    std::array<std::int64_t, 2> steps{};       // commanded signed microsteps per axis (x, y)
    std::array<double, 2> rate_steps_per_s{};  // commanded per-axis step rate (what the programmed F implies)
    TimePs t_begin_ps = 0;        // execution window as the controller reports it (e.g. busy)
    TimePs t_end_ps = 0;
};

struct RunInput {
    std::vector<AxisTrace> axes;    // x, y (analyze may give one)
    std::vector<MoveSpec> moves;    // sorted by t_begin_ps; empty for analyze
    std::vector<ToolSample> tool;   // sorted by t_ps; empty for analyze
    std::optional<EdgeLog> laser;
    TimePs t_job_start_ps = 0;
    TimePs t_job_end_ps = 0;
    DriverLimits limits;
    double run_split_tolerance = 0.005;  // analyze only: relative period change that starts a new run
};

}  // namespace cnc::metrics
