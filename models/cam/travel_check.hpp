// seed 003 §5.6's proposed CAM check: a drawing that leaves the machine's work area is refused before any G-code
// is written, naming the entity (its file line, type and layer) and the axis's travel.
#pragma once
#include "cam/drawing.hpp"
#include "host/core/machine.hpp"

namespace cnc::cam {

// Throws cnc::BadInput for the first entity whose path (an arc's extremes too) leaves [0, travel_mm] on X or Y,
// when the machine has soft limits and a travel on that axis.
void check_travel(const Drawing& drawing, const host::MachineModel& machine);

}  // namespace cnc::cam
