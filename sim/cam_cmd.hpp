// `cncsim cam DRAWING.dxf`: the drawing-to-G-code CAM (docs/cam.md). Prints what the ordering gives (entities,
// routes, rapids, laser cycles, lengths), writes the G-code with --out; --compare-orders sets every ordering side by
// side, with each one's job time on --arch when one is named (a `cncsim run` of its G-code each).
#pragma once
#include <ostream>
#include <string>
#include <vector>

namespace cnc::sim {

struct CamCommand {
    std::string drawing;
    std::string machine;  // --machine: its travel bounds the drawing
    std::string order;    // --order: sets cam.order
    std::string out;      // --out: the G-code file
    std::string arch;     // --arch: with --compare-orders, run each ordering's G-code on it
    bool compare_orders = false;
    bool skip_unread = false;
    std::vector<std::string> sets;
};

// `self`: this program, for the runs of --arch. Returns the exit code.
int cmd_cam(const CamCommand& c, const std::string& self, std::ostream& out);

}  // namespace cnc::sim
