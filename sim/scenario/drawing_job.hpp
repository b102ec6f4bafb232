// A DXF job turned into the G-code every architecture reads (docs/cam.md). Loading a scenario only names the
// drawing; the CLI calls this before it runs or checks the job, so that loading reads and writes no job file.
#pragma once
#include "scenario/scenario.hpp"

namespace cnc::sim {

// With a drawing (Scenario::drawing_path): reads it, checks it against the machine's travel, orders it
// (cam.order), writes its G-code to cam.gcode (a temporary file, removed when cncsim ends, without one) and points
// job_path at it. BadInput naming the drawing's file and line (or scenario.job, cam.gcode). Without one: nothing.
void write_drawing_job(Scenario& s);

}  // namespace cnc::sim
