// Scenario keys of the drawing-to-G-code CAM ([cam]): a job that is a DXF drawing (scenario.job = "part.dxf", or
// `cncsim run part.dxf`) is turned into G-code before anything runs (drawing_job.hpp), with these settings
// (docs/cam.md).
#pragma once
#include <string>

#include "cam/cam_job.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct CamSettings {
    cam::CamOptions options;
    std::string gcode_path;   // cam.gcode: where a DXF job's G-code goes; empty: a temporary file
    std::string gcode_where;  // where cam.gcode was set, for messages
};

void read_cam_settings(KeyReader& r, CamSettings& s);

// Whether a job file is a drawing for the CAM (.dxf, any case).
[[nodiscard]] bool is_drawing(const std::string& path);

}  // namespace cnc::sim
