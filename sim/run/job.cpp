#include "run/job.hpp"

#include "common/bad_input.hpp"
#include "host/core/soft_limits.hpp"
#include "host/core/steps_file.hpp"

namespace cnc::sim {

Job load_job(const Scenario& s) {
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
        return job;
    }
    job.program = host::interpret_file(s.job_path, s.interpreter);
    host::check_soft_limits(*job.program, s.machine);
    return job;
}

}  // namespace cnc::sim
