#include "run/job.hpp"

#include <filesystem>

#include "common/bad_input.hpp"
#include "host/core/soft_limits.hpp"
#include "host/core/steps_file.hpp"
#include "run/job_limits.hpp"

namespace cnc::sim {

namespace {

// The job file must be a file that exists: named by its key, not as whatever the reader would make of it.
void check_job_file(const Scenario& s) {
    std::error_code ec;
    const std::filesystem::file_status st = std::filesystem::status(s.job_path, ec);
    if (!std::filesystem::exists(st)) throw BadInput(s.job_key, "the job file " + s.job_path + " does not exist");
    if (std::filesystem::is_directory(st)) throw BadInput(s.job_key, s.job_path + " is a folder, not a job file");
}

}  // namespace

Job load_job(const Scenario& s) {
    check_job_file(s);
    if (s.architecture == "fpga-uart") check_numerators(s);
    Job job;
    if (s.job_format == JobFormat::Steps) {
        job.steps_file = host::load_steps_file(s.job_path);
        for (host::MotionSegment& seg : job.steps_file) {
            if (seg.feed == 0 && !s.allow_feed_zero) {
                throw BadInput(s.job_path + ": segment " + std::to_string(seg.index),
                               "FeedRate 0 (allowed 1 .. 65535; host.allow_feed_zero = true sends it as the appendix "
                               "RTL would run it: 62500 clocks per step on both axes)");
            }
            seg.dx_mm = static_cast<double>(seg.steps_x) / s.machine.x.steps_per_mm();
            seg.dy_mm = static_cast<double>(seg.steps_y) / s.machine.y.steps_per_mm();
        }
        if (job.steps_file.empty()) job.warnings.push_back({"empty_job", s.job_path, "the steps file has no segment"});
        return job;
    }
    job.program = host::interpret_file(s.job_path, s.interpreter);
    host::check_soft_limits(*job.program, s.machine);
    check_job_limits(*job.program, s);
    if (job.program->moves.empty()) {
        const std::string what = "the job has no XY move (" + std::to_string(job.program->lines) +
                                 " lines: empty, or comments and words that move nothing)";
        if (s.interpreter.policy == host::GcodePolicy::Strict) {
            throw BadInput(s.job_path, what + "; scenario.gcode_policy = \"strict\" refuses it");
        }
        job.warnings.push_back({"empty_job", s.job_path, what + ": nothing to measure"});
    }
    return job;
}

}  // namespace cnc::sim
