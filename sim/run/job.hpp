// The job as the host reads it: the programmed moves of a G-code job, or the packet list of a seed 000 steps
// file (which has no programmed geometry). What each architecture's host makes of it is its own business.
#pragma once
#include <optional>
#include <vector>

#include "architectures/architecture.hpp"
#include "common/warning.hpp"
#include "host/core/cam.hpp"
#include "host/core/gcode.hpp"
#include "run/program_report.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

struct Job {
    // G-code job; without its moves (Program::moves empty, move_count counts them) when the architecture streams
    // the job: it reads them from the file again as it sends them (host::GcodeStream).
    std::optional<host::Program> program;
    std::vector<host::MotionSegment> steps_file;  // steps-file job (JobUse::takes_steps_file)
    std::vector<Warning> warnings;                // about the job as a whole (one without a move)
    // About its moves: the laser against the job's intent, feeds held to the axis limits (run/held_feeds.hpp).
    std::vector<Warning> move_warnings;
};

// Reads the job as `architecture` takes it (one pass over the file, the moves kept unless it streams the job) and
// checks it against the machine (run/job_limits.hpp, Architecture::check_machine and check_move) before anything
// is simulated. A job without a move (empty, comments only) is a warning, and bad input under
// scenario.gcode_policy = "strict".
Job load_job(const Scenario& scenario, const Architecture& architecture);

}  // namespace cnc::sim
