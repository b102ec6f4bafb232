// `cncsim motor-curve SCENARIO` or `cncsim motor-curve --machine MACHINE.toml`: the configured motor, driver current
// and supply against the scenario's (the machine file's) load on one axis: pull-out torque and the load's required
// torque over step rates, and the pull-in rate.
#pragma once
#include <ostream>
#include <string>
#include <vector>

namespace cnc::sim {

// One of scenario_path and machine_path (else BadInput). Prints the table and the pull-in rate to `out`, writes the
// table as CSV to csv_path; returns the exit code.
int cmd_motor_curve(const std::string& scenario_path, const std::string& machine_path,
                    const std::vector<std::string>& sets, const std::string& axis, const std::string& csv_path,
                    std::ostream& out);

}  // namespace cnc::sim
