#include "systems/spi_fpga/spi_fpga_job.hpp"

#include <optional>

#include "host/servo/core/laser_bit.hpp"

namespace cnc::sim {

JobAhead read_job_ahead(const Scenario& s, const Job& job, const ArchPace& pace) {
    JobAhead ahead;
    ahead.servo.rest_points = host::servo::count_rest_points(*open_plan(s));
    host::GcodeStream moves(s.job_path, s.interpreter, false);
    EstimateSum sum(job.program->wait_s_between(0, job.program->move_count + 1), pace);
    for (std::optional<host::ProgrammedMove> m = moves.next(); m; m = moves.next()) {
        sum.add(*m);
        ahead.servo.laser_intended.push_back(m->laser_intended());
    }
    ahead.estimate = sum.finish();
    return ahead;
}

std::shared_ptr<host::planner::PlanFeed> open_plan(const Scenario& s) {
    return std::make_shared<host::planner::PlanFeed>(
        s.spi_fpga.planner, std::make_unique<host::GcodeStream>(s.job_path, s.interpreter, false));
}

}  // namespace cnc::sim
