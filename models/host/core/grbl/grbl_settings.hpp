// The grbl settings a sender writes after grbl's start-up message so that grbl runs on the scenario's machine:
// $100/$101 steps per mm, $110/$111 maximum rate (mm/min), $120/$121 acceleration (mm/s^2), $32 laser mode
// (grbl 1.1's settings list), then the scenario's own "$N=value" lines, which override a derived one.
#pragma once
#include <string>
#include <vector>

#include "host/core/grbl/grbl_lines.hpp"
#include "host/core/machine.hpp"

namespace cnc::host::grbl {

// `overrides`: "$N=value" texts as the scenario gives them (validated: BadInput at `where` naming the text). Each
// line's `where` says what it comes from: `where` for an override, "`file`: machine.x.max_velocity_mm_per_s x 60"
// for a derived one.
[[nodiscard]] std::vector<SendLine> machine_settings(const MachineModel& machine, bool laser_mode,
                                                     const std::vector<std::string>& overrides,
                                                     const std::string& where, const std::string& file);

}  // namespace cnc::host::grbl
