// What the G-code job asked for beyond the XY moves, for the report: the words this machine ignored (with their
// lines), the host waits (dwells, operator pauses, Z moves timed as host dead time), and where the laser the
// architecture switches differs from the job's intent.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "architectures/architecture.hpp"
#include "common/warning.hpp"
#include "host/core/gcode.hpp"

namespace cnc::sim {

nlohmann::json program_json(const host::Program& program);
std::string program_text(const host::Program& program);

// A warning where the laser of move `m` of `filename` differs from the job's intent, placed at its G-code line.
void laser_warnings(const host::ProgrammedMove& m, const std::string& filename, LaserSwitching switching,
                    std::vector<Warning>& out);

}  // namespace cnc::sim
