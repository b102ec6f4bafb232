#include "run/job.hpp"

#include <filesystem>
#include <optional>

#include "architectures/catalog.hpp"
#include "common/bad_input.hpp"
#include "host/core/soft_limits.hpp"
#include "host/core/steps_file.hpp"
#include "run/held_feeds.hpp"
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

// The architectures that take a steps file, for messages.
std::string steps_file_architectures() {
    std::string names;
    for (const Architecture* a : architectures()) {
        if (a->job_use().takes_steps_file) names += (names.empty() ? "" : ", ") + a->name();
    }
    return names;
}

}  // namespace

Job load_job(const Scenario& s, const Architecture& architecture) {
    check_job_file(s);
    architecture.check_machine(s);
    const JobUse use = architecture.job_use();
    Job job;
    if (s.job_format == JobFormat::Steps) {
        if (!use.takes_steps_file) {
            throw BadInput(s.file + ": scenario.job",
                           architecture.name() +
                               " needs a G-code job: a steps file (seed 000's packet "
                               "list) holds no programmed moves for its host, and runs only on " +
                               steps_file_architectures());
        }
        job.steps_file = host::load_steps_file(s.job_path);
        for (host::MotionSegment& seg : job.steps_file) {
            seg.dx_mm = static_cast<double>(seg.steps_x) / s.machine.x.steps_per_mm();
            seg.dy_mm = static_cast<double>(seg.steps_y) / s.machine.y.steps_per_mm();
        }
        if (job.steps_file.empty()) job.warnings.push_back({"empty_job", s.job_path, "the steps file has no segment"});
        return job;
    }
    // The checks in the order of the whole program's: the file's own problems (thrown at its end), then the first
    // move past the soft limits, then the first past the machine's limits.
    host::GcodeStream stream(s.job_path, s.interpreter, !use.streams_job);
    JobLimits limits(s, architecture, s.job_path);
    HeldFeedWarnings held_feeds(s.machine, s.job_path);
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
        laser_warnings(*move, s.job_path, use.laser_switching, job.move_warnings);
        held_feeds.add(*move);
    }
    held_feeds.finish(job.move_warnings);
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
