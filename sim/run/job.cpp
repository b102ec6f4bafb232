#include "run/job.hpp"

#include <filesystem>
#include <optional>

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

Job load_job(const Scenario& s, LaserSwitching switching, bool keep_moves) {
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
    // The checks in the order of the whole program's: the file's own problems (thrown at its end), then the first
    // move past the soft limits, then the first past the machine's limits.
    host::GcodeStream stream(s.job_path, s.interpreter, keep_moves);
    JobLimits limits(s, s.job_path);
    std::optional<BadInput> soft_breach, limit_breach;
    for (std::size_t i = 0; const std::optional<host::ProgrammedMove> move = stream.next(); ++i) {
        try {
            if (!soft_breach) host::check_soft_limits(*move, s.machine, s.job_path);
        } catch (const BadInput& e) {
            soft_breach = e;
        }
        try {
            if (!limit_breach) limits.check(*move, i, stream.program().waits);
        } catch (const BadInput& e) {
            limit_breach = e;
        }
        laser_warnings(*move, s.job_path, switching, job.move_warnings);
    }
    if (soft_breach) throw *soft_breach;
    if (limit_breach) throw *limit_breach;
    limits.finish(stream.program().waits);
    job.program = stream.take();
    if (job.program->move_count == 0) {
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
