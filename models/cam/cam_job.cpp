#include "cam/cam_job.hpp"

#include "cam/travel_check.hpp"

namespace cnc::cam {

Drawing load_drawing(const std::string& path, const CamOptions& options, const host::MachineModel& machine) {
    Drawing d = read_dxf(path, options.dxf);
    check_travel(d, machine);
    return d;
}

CamOutput cam_output(const Drawing& drawing, Order order, const CamOptions& options) {
    CamOutput out;
    out.routes = order_routes(drawing.entities, order, options.ordering);
    out.stats = route_stats(drawing.entities, out.routes, options.ordering.start_mm);
    out.gcode = write_gcode(drawing.entities, out.routes, options.gcode);
    return out;
}

}  // namespace cnc::cam
