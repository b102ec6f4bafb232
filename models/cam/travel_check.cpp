#include "cam/travel_check.hpp"

#include "common/bad_input.hpp"
#include "host/core/soft_limits.hpp"

namespace cnc::cam {

void check_travel(const Drawing& drawing, const host::MachineModel& machine) {
    for (const Entity& e : drawing.entities) {
        const geom::Box b = e.path.bounds();
        auto why = soft_limit_breach(machine, host::MachineAxis::X, b.min.x_mm, b.max.x_mm);
        if (!why) why = soft_limit_breach(machine, host::MachineAxis::Y, b.min.y_mm, b.max.y_mm);
        if (why) {
            throw BadInput(drawing.file + ":" + std::to_string(e.line),
                           e.type + " (entity " + std::to_string(e.source) + ", layer " + e.layer +
                               ") is outside the machine's work area: " + *why);
        }
    }
}

}  // namespace cnc::cam
