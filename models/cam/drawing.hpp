// A drawing as the CAM reads it (seed 000 §3.3, seed 003 §5.1.1): lines and arcs in mm, each with the DXF entity
// it came from, its layer and its colour. No SystemC, no DXF: dxf_reader.hpp fills it.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "common/geometry.hpp"

namespace cnc::cam {

// AutoCAD colour index of red: seed 000 §3.3's form cuts red entities at the cut feed, others at the engrave feed.
inline constexpr int kRedColour = 1;

struct Entity {
    geom::Segment path;  // in mm; a CIRCLE is a full arc from its angle-0 point, counter-clockwise
    std::string type;    // the DXF entity it came from: LINE, ARC, CIRCLE, LWPOLYLINE, POLYLINE
    int source = 0;      // 0-based number of that DXF entity in the ENTITIES section (a polyline's segments share it)
    int line = 0;        // the file line it starts on
    std::string layer;
    int colour = 7;  // AutoCAD colour index, BYLAYER resolved
    [[nodiscard]] bool cut() const { return colour == kRedColour; }
};

struct Drawing {
    std::string file;
    std::vector<Entity> entities;       // drawing order
    int entities_read = 0;              // DXF entities read (a polyline counts once)
    std::map<std::string, int> unread;  // entity types the CAM does not read, with their counts (when skipped)
};

// The same path run the other way: an arc turns the other way round the same centre.
geom::Segment reversed(const geom::Segment& s);

// The segment a polyline's bulge gives from `from` to `to`: DXF group 42, bulge = tan(included angle / 4),
// positive counter-clockwise; 0 is a straight line.
geom::Segment bulge_segment(geom::Vec2 from, geom::Vec2 to, double bulge);

}  // namespace cnc::cam
