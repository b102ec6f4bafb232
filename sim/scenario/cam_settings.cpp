#include "scenario/cam_settings.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace cnc::sim {

void read_cam_settings(KeyReader& r, CamSettings& s) {
    cam::CamOptions& o = s.options;
    o.order = cam::parse_order(r.get_choice(
        "cam.order", "seed000", cam::order_names(),
        "the order a DXF job's entities are cut in: selection (the drawing's), seed000 (seed 000 §3.3 Path "
        "Optimize), seed003 (seed 003 §5.1.2's alignment loop), optimized (ours: nearest neighbour and 2-opt over "
        "seed000's chains; docs/cam.md)"));
    o.gcode.engrave_feed_mm_per_min =
        r.get_float("cam.engrave_feed_mm_per_min", o.gcode.engrave_feed_mm_per_min, 1.0, 65535.0,
                    "feed of every entity but the red ones, mm/min (seed 000's form: Feed Rate; its sample: 800)");
    o.gcode.cut_feed_mm_per_min =
        r.get_float("cam.cut_feed_mm_per_min", o.gcode.cut_feed_mm_per_min, 1.0, 65535.0,
                    "feed of the red entities (colour 1, or BYLAYER on a red layer), mm/min (seed 000's form: Cut "
                    "Feed Rate, no value given)");
    o.gcode.laser_power = r.get_float("cam.laser_power", o.gcode.laser_power, 0.0, 65535.0,
                                      "the S word with each route's M3 (seed 000's sample: M3 S255)");
    o.ordering.join_tolerance_mm =
        r.get_float("cam.join_tolerance_mm", o.ordering.join_tolerance_mm, 1e-9, 10.0,
                    "endpoints this close, mm, are one point (seed 000's JoinTolerance, default 0.001)");
    o.ordering.seed003_tolerance_mm = r.get_optional_float(
        "cam.seed003_tolerance_mm", 1e-9, 10.0, "none: the seed's float == comparisons",
        "cam.order = seed003: points this close, mm, are one point (our fix); unset, seed 003's code compares its "
        "float coordinates with ==");
    o.dxf.skip_unread = r.get_bool("cam.skip_unread", o.dxf.skip_unread,
                                   "leave out entity types the CAM does not read (SPLINE, TEXT, ...) and list them; "
                                   "false: refuse the drawing, listing them");
    s.gcode_path = r.get_string("cam.gcode", "",
                                "where a DXF job's G-code is written (relative to the working folder); empty: a "
                                "temporary file, removed when cncsim ends");
    s.gcode_where = r.where("cam.gcode");
}

bool is_drawing(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".dxf";
}

}  // namespace cnc::sim
