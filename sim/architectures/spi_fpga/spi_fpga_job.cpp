#include "architectures/spi_fpga/spi_fpga_job.hpp"

#include "architectures/planner/planned_job.hpp"
#include "host/servo/core/laser_bit.hpp"

namespace cnc::sim {

JobAhead read_job_ahead(const Scenario& s, const Job& job, const host::planner::PlannerConfig& cfg) {
    JobAhead ahead;
    ahead.servo.rest_points = host::servo::count_rest_points(*open_plan(s, cfg));
    ahead.estimate = planned_estimate(s, job, cfg, [&ahead](const host::ProgrammedMove& m) {
        ahead.servo.laser_intended.push_back(m.laser_intended());
    });
    return ahead;
}

}  // namespace cnc::sim
