// Reading DXF drawings: polyline bulges, units, layers and colours, and the feed each colour gets.
#include <gtest/gtest.h>

#include <cmath>

#include "cam/dxf_reader.hpp"
#include "cam/gcode_writer.hpp"
#include "cam/ordering.hpp"
#include "dxf_text.hpp"
#include "support/test_path.hpp"

namespace cnc::cam {
namespace {

// The arc a bulge b gives between two points, from its included angle theta = 4 atan(b): radius (c/2)/sin(theta/2)
// and the centre r cos(theta/2) from the chord's midpoint, on the left of the chord for a counter-clockwise arc.
struct Expected {
    geom::Vec2 centre;
    double radius;
    double sweep_rad;
};
Expected bulge_arc(geom::Vec2 a, geom::Vec2 b, double bulge) {
    const double theta = 4.0 * std::atan(bulge);
    const double c = std::hypot(b.x_mm - a.x_mm, b.y_mm - a.y_mm);
    const double r = c / 2.0 / std::sin(std::fabs(theta) / 2.0);
    const double to_centre = r * std::cos(theta / 2.0) * (theta > 0 ? 1.0 : -1.0);
    const geom::Vec2 mid{(a.x_mm + b.x_mm) / 2.0, (a.y_mm + b.y_mm) / 2.0};
    const geom::Vec2 left{-(b.y_mm - a.y_mm) / c, (b.x_mm - a.x_mm) / c};
    return {{mid.x_mm + left.x_mm * to_centre, mid.y_mm + left.y_mm * to_centre}, r, theta};
}

void expect_arc(const Entity& e, const Expected& x) {
    ASSERT_TRUE(e.path.is_arc);
    EXPECT_NEAR(e.path.center.x_mm, x.centre.x_mm, 1e-9);
    EXPECT_NEAR(e.path.center.y_mm, x.centre.y_mm, 1e-9);
    EXPECT_NEAR(e.path.radius_mm(), x.radius, 1e-9);
    EXPECT_NEAR(e.path.sweep_rad, x.sweep_rad, 1e-9);
}

TEST(CamDxf, PolylineBulgesGiveTheArcsOfTheBulgeFormula) {
    const std::string path = test::test_path("bulges.dxf");
    // (0,0) -b 0.5-> (10,0) -b -1-> (20,0) -line-> (20,10) -b 0.25 (closing)-> (0,0)
    test::DxfText().lwpolyline({{0, 0, 0.5}, {10, 0, -1}, {20, 0, 0}, {20, 10, 0.25}}, true).write(path);
    const Drawing d = read_dxf(path, {});
    ASSERT_EQ(d.entities.size(), 4u);
    EXPECT_EQ(d.entities_read, 1);
    expect_arc(d.entities[0], bulge_arc({0, 0}, {10, 0}, 0.5));
    EXPECT_NEAR(d.entities[0].path.radius_mm(), 6.25, 1e-12);    // theta = 106.26 deg: r = 10 / (2 sin 53.13 deg)
    expect_arc(d.entities[1], bulge_arc({10, 0}, {20, 0}, -1));  // a clockwise half circle about (15,0)
    EXPECT_NEAR(d.entities[1].path.center.x_mm, 15.0, 1e-12);
    EXPECT_FALSE(d.entities[2].path.is_arc);
    expect_arc(d.entities[3], bulge_arc({20, 10}, {0, 0}, 0.25));
    for (const Entity& e : d.entities) EXPECT_EQ(e.type, "LWPOLYLINE");

    const std::string g = write_gcode(d.entities, order_routes(d.entities, Order::Selection, {}), {});
    EXPECT_NE(g.find("G3 X10.000 Y0.000 I5.000 J3.750 F800\n"), std::string::npos) << g;
    EXPECT_NE(g.find("G2 X20.000 Y0.000 I5.000 J0.000 F800\n"), std::string::npos) << g;
}

TEST(CamDxf, OldStylePolylinesReadAsLightweightOnes) {
    const std::string path = test::test_path("polyline.dxf");
    test::DxfText()
        .polyline({{0, 0, 0.5}, {10, 0, -1}, {20, 0, 0}, {20, 10, 0.25}}, true)
        .line(0, 0, -5, 0)
        .write(path);
    const Drawing d = read_dxf(path, {});
    ASSERT_EQ(d.entities.size(), 5u);
    EXPECT_EQ(d.entities_read, 2);
    expect_arc(d.entities[0], bulge_arc({0, 0}, {10, 0}, 0.5));
    expect_arc(d.entities[1], bulge_arc({10, 0}, {20, 0}, -1));
    expect_arc(d.entities[3], bulge_arc({20, 10}, {0, 0}, 0.25));
    EXPECT_EQ(d.entities[0].type, "POLYLINE");
    EXPECT_EQ(d.entities[4].type, "LINE");
    EXPECT_EQ(d.entities[4].source, 1);
}

TEST(CamDxf, InsunitsScaleTheDrawingToMillimetres) {
    const std::string path = test::test_path("inches.dxf");
    test::DxfText().insunits(1).line(0, 0, 2, 1).write(path);
    const Drawing d = read_dxf(path, {});
    EXPECT_DOUBLE_EQ(d.entities[0].path.end.x_mm, 50.8);
    EXPECT_DOUBLE_EQ(d.entities[0].path.end.y_mm, 25.4);
}

// An arc whose extrusion direction is -Z is drawn in a mirrored coordinate system (world x = -x): the quarter arc
// from 0 to 90 degrees about (10,0) is, seen from +Z, the clockwise one from (-15,0) to (-10,5) about (-10,0).
TEST(CamDxf, MirroredArcsTurnClockwise) {
    const std::string path = test::test_path("mirrored.dxf");
    test::DxfText().arc(10, 0, 5, 0, 90, 256, -1.0).write(path);
    const Drawing d = read_dxf(path, {});
    ASSERT_EQ(d.entities.size(), 1u);
    const geom::Segment& s = d.entities[0].path;
    EXPECT_NEAR(s.center.x_mm, -10.0, 1e-12);
    EXPECT_NEAR(s.start.x_mm, -15.0, 1e-12);
    EXPECT_NEAR(s.start.y_mm, 0.0, 1e-12);
    EXPECT_NEAR(s.end.x_mm, -10.0, 1e-12);
    EXPECT_NEAR(s.end.y_mm, 5.0, 1e-12);
    EXPECT_NEAR(s.sweep_rad, -M_PI / 2.0, 1e-12);
}

TEST(CamDxf, RedEntitiesAndRedLayersGetTheCutFeed) {
    const std::string path = test::test_path("colours.dxf");
    test::DxfText()
        .layer("CUT", 1)
        .layer("MARK", 3)
        .line(0, 0, 10, 0, 256, "CUT")   // red by layer
        .line(10, 0, 10, 10, 1, "MARK")  // red by its own colour
        .line(10, 10, 0, 10, 256, "MARK")
        .line(0, 10, 0, 0, 5, "CUT")  // blue on the red layer
        .write(path);
    const Drawing d = read_dxf(path, {});
    ASSERT_EQ(d.entities.size(), 4u);
    EXPECT_EQ(d.entities[0].colour, 1);
    EXPECT_EQ(d.entities[0].layer, "CUT");
    EXPECT_EQ(d.entities[2].colour, 3);
    GcodeOptions o;
    o.engrave_feed_mm_per_min = 900;
    o.cut_feed_mm_per_min = 150;
    const std::string g = write_gcode(d.entities, order_routes(d.entities, Order::Selection, {}), o);
    EXPECT_NE(g.find("G1 X10.000 Y0.000 F150\n"), std::string::npos) << g;
    EXPECT_NE(g.find("G1 X10.000 Y10.000 F150\n"), std::string::npos) << g;
    EXPECT_NE(g.find("G1 X0.000 Y10.000 F900\n"), std::string::npos) << g;
    EXPECT_NE(g.find("G1 X0.000 Y0.000 F900\n"), std::string::npos) << g;
}

}  // namespace
}  // namespace cnc::cam
