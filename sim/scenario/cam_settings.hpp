// Scenario keys of the drawing-to-G-code CAM ([cam]): a job that is a DXF drawing (scenario.job = "part.dxf", or
// `cncsim run part.dxf`) is turned into G-code before anything runs, with these settings (docs/cam.md).
#pragma once
#include <string>

#include "cam/cam_job.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct CamSettings {
    cam::CamOptions options;
    std::string gcode_path;  // cam.gcode: where a DXF job's G-code goes; empty: a temporary file
};

void read_cam_settings(KeyReader& r, CamSettings& s);

// Whether a job file is a drawing for the CAM (.dxf, any case).
[[nodiscard]] bool is_drawing(const std::string& path);

// The drawing `drawing_path` as G-code in the file cam.gcode names (a temporary file, removed when cncsim ends,
// without one); returns that file's path. BadInput as the CAM throws, or naming cam.gcode when it cannot be written.
std::string drawing_to_gcode(const std::string& drawing_path, const CamSettings& s, const host::MachineModel& machine,
                             const KeyReader& r);

}  // namespace cnc::sim
