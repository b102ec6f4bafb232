// The job as the host reads it: the programmed moves of a G-code job, or the packet list of a seed 000 steps
// file (which has no programmed geometry). What each architecture's host makes of it is its own business.
#pragma once
#include <optional>
#include <vector>

#include "host/core/cam.hpp"
#include "host/core/gcode.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

struct Job {
    std::optional<host::Program> program;         // G-code job
    std::vector<host::MotionSegment> steps_file;   // steps-file job (fpga-uart only)
};

Job load_job(const Scenario& scenario);

}  // namespace cnc::sim
