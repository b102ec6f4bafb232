// The job as the host holds it: the programmed moves (G-code jobs) and the motion segments the CAM made of
// them, or the segments of a seed 000 steps file (which has no programmed geometry).
#pragma once
#include <optional>
#include <vector>

#include "host/core/cam.hpp"
#include "host/core/gcode.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

struct Job {
    std::optional<host::Program> program;
    std::vector<host::MotionSegment> segments;
};

Job load_job(const Scenario& scenario);

}  // namespace cnc::sim
