// A drawing through the whole CAM: read (dxf_reader), checked against the machine's travel (travel_check), ordered
// (ordering), written as G-code (gcode_writer). What `cncsim cam` and a scenario with a DXF job run.
#pragma once
#include <string>
#include <vector>

#include "cam/dxf_reader.hpp"
#include "cam/gcode_writer.hpp"
#include "cam/ordering.hpp"
#include "cam/route_stats.hpp"
#include "host/core/machine.hpp"

namespace cnc::cam {

struct CamOptions {
    DxfOptions dxf;
    Order order = Order::Seed000;
    OrderOptions ordering;
    GcodeOptions gcode;
};

// The drawing read and checked: BadInput as read_dxf and check_travel throw.
Drawing load_drawing(const std::string& path, const CamOptions& options, const host::MachineModel& machine);

struct CamOutput {
    std::vector<Route> routes;
    RouteStats stats;
    std::string gcode;
};

CamOutput cam_output(const Drawing& drawing, Order order, const CamOptions& options);

}  // namespace cnc::cam
