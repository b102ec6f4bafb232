// Soft limits (grbl's $20): on an axis with a travel (machine.<axis>.travel_mm > 0) the tool must stay within
// [0, travel_mm] in machine coordinates, or the carriage would hit the end of the axis. Checked on the
// programmed path before anything is sent, as grbl checks each motion command before it plans it.
#pragma once
#include <optional>
#include <string>

#include "host/core/gcode.hpp"
#include "host/core/machine.hpp"

namespace cnc::host {

enum class MachineAxis { X, Y };

// Why the span lo_mm .. hi_mm on `axis` breaks the soft limits, or nothing (also when they are off or the axis
// has no travel). The text names the axis, the value, the travel key and how to switch the check off.
[[nodiscard]] std::optional<std::string> soft_limit_breach(const MachineModel& machine, MachineAxis axis, double lo_mm,
                                                           double hi_mm);

// Throws cnc::BadInput("file:line", ...) for the first move whose path leaves an axis' travel: lines by their
// end points, arcs by the extremes they pass through.
void check_soft_limits(const Program& program, const MachineModel& machine);
// One move of `filename`, as a streamed job's moves are read.
void check_soft_limits(const ProgrammedMove& move, const MachineModel& machine, const std::string& filename);

}  // namespace cnc::host
