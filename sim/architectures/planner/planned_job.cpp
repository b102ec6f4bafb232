#include "architectures/planner/planned_job.hpp"

#include <algorithm>
#include <optional>

#include "host/core/planner/path_limits.hpp"
#include "host/core/planner/speed_profile.hpp"

namespace cnc::sim {

std::shared_ptr<host::planner::PlanFeed> open_plan(const Scenario& s, const host::planner::PlannerConfig& cfg) {
    return std::make_shared<host::planner::PlanFeed>(
        cfg, std::make_unique<host::GcodeStream>(s.job_path, s.interpreter, false));
}

ArchPace planner_pace(const host::planner::PlannerConfig& cfg) {
    ArchPace p;
    p.max_speed_x_mm_per_s = cfg.x.max_velocity_mm_per_s;
    p.max_speed_y_mm_per_s = cfg.y.max_velocity_mm_per_s;
    host::planner::PathLimits slowest{};
    slowest.accel_mm_per_s2 = 0.5 * std::min(cfg.x.max_accel_mm_per_s2, cfg.y.max_accel_mm_per_s2);
    slowest.jerk_mm_per_s3 = std::min(cfg.x.max_jerk_mm_per_s3, cfg.y.max_jerk_mm_per_s3);
    p.ramp_s = [profile = cfg.profile, slowest](double speed_mm_per_s) {
        return host::planner::transition_time_s(profile, 0.0, speed_mm_per_s, slowest);
    };
    return p;
}

JobEstimate planned_estimate(const Scenario& s, const Job& job, const host::planner::PlannerConfig& cfg,
                             const std::function<void(const host::ProgrammedMove&)>& each) {
    host::GcodeStream moves(s.job_path, s.interpreter, false);
    EstimateSum sum(job.program->wait_s_between(0, job.program->move_count + 1), planner_pace(cfg));
    for (std::optional<host::ProgrammedMove> m = moves.next(); m; m = moves.next()) {
        sum.add(*m);
        if (each) each(*m);
    }
    return sum.finish();
}

}  // namespace cnc::sim
