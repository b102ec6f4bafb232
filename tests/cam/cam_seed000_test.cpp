// seed 000 §3.3's worked example: the 19 entities of its Table 3.1 as a DXF, through "Path Optimize".
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cam/dxf_reader.hpp"
#include "cam/gcode_writer.hpp"
#include "cam/ordering.hpp"
#include "cam/route_stats.hpp"
#include "dxf_text.hpp"
#include "host/core/gcode.hpp"
#include "support/test_path.hpp"

namespace cnc::cam {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

// Table 3.1: start, end and, for an arc, I and J (centre minus start); every arc counter-clockwise, as AutoCAD
// stores them.
struct Row {
    double x1, y1, x2, y2;
    bool arc;
    double i, j;
};
const Row kTable31[] = {
    {75, 50, 75, 100, false, 0, 0},    {125, 125, 125, 175, false, 0, 0},    {175, 175, 175, 125, false, 0, 0},
    {200, 100, 250, 100, false, 0, 0}, {275, 125, 325, 175, false, 0, 0},    {350, 150, 350, 225, false, 0, 0},
    {300, 250, 250, 250, false, 0, 0}, {75, 100, 125, 125, false, 0, 0},     {175, 175, 125, 175, true, -25, 0},
    {175, 125, 200, 100, true, 25, 0}, {250, 100, 250, 125, false, 0, 0},    {250, 125, 275, 125, false, 0, 0},
    {350, 150, 325, 175, false, 0, 0}, {300, 250, 350, 225, true, 50, 37.5}, {250, 250, 200, 225, true, 0, -62.5},
    {25, 50, 25, 225, false, 0, 0},    {25, 225, 200, 225, false, 0, 0},     {25, 50, 75, 50, false, 0, 0},
};

std::string example_dxf() {
    test::DxfText dxf;
    for (const Row& r : kTable31) {
        if (!r.arc) {
            dxf.line(r.x1, r.y1, r.x2, r.y2);
            continue;
        }
        const double cx = r.x1 + r.i, cy = r.y1 + r.j;
        dxf.arc(cx, cy, std::hypot(r.i, r.j), std::atan2(r.y1 - cy, r.x1 - cx) * kRadToDeg,
                std::atan2(r.y2 - cy, r.x2 - cx) * kRadToDeg);
    }
    dxf.circle(250, 200, 25);  // E18: the circle from (275,200), I = -25, J = 0
    const std::string path = test::test_path("example.dxf");
    dxf.write(path);
    return path;
}

std::vector<std::string> lines_starting(const std::string& text, const std::vector<std::string>& prefixes) {
    std::vector<std::string> found;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        for (const std::string& p : prefixes) {
            if (line.rfind(p, 0) == 0) found.push_back(line);
        }
    }
    return found;
}

TEST(CamSeed000, WorkedExampleGivesTheDerivedRoute) {
    const Drawing d = read_dxf(example_dxf(), {});
    ASSERT_EQ(d.entities.size(), 19u);
    const std::vector<Route> routes = order_routes(d.entities, Order::Seed000, {});
    ASSERT_EQ(routes.size(), 2u);
    // seed 000 §3.3, re-derived from A.1: E3r, E9r, E2r, E8, E1r, E7r, E0r, E17r, E15, E16, E14r, E6r, E13, E5r,
    // E12, E4r, E11r, E10r from (250,100); then the circle alone, reversed: its ends are equal, so its end is the
    // "smaller" one and A.1 turns it round.
    const std::vector<std::pair<int, bool>> main = {
        {3, true},   {9, true},  {2, true}, {8, false},  {1, true}, {7, true},   {0, true}, {17, true}, {15, false},
        {16, false}, {14, true}, {6, true}, {13, false}, {5, true}, {12, false}, {4, true}, {11, true}, {10, true}};
    ASSERT_EQ(routes[0].size(), main.size());
    for (std::size_t k = 0; k < main.size(); ++k) {
        EXPECT_EQ(d.entities[routes[0][k].entity].source, main[k].first) << "step " << k;
        EXPECT_EQ(routes[0][k].reversed, main[k].second) << "step " << k << " (E" << main[k].first << ")";
    }
    ASSERT_EQ(routes[1].size(), 1u);
    EXPECT_EQ(d.entities[routes[1][0].entity].source, 18);
    EXPECT_TRUE(routes[1][0].reversed);

    const RouteStats st = route_stats(d.entities, routes, {0, 0});
    EXPECT_EQ(st.routes, 2);
    EXPECT_EQ(st.moves, 19);
}

TEST(CamSeed000, WorkedExampleGcodeHasTwoRapidsAndNineteenCuts) {
    const Drawing d = read_dxf(example_dxf(), {});
    const std::string g = write_gcode(d.entities, order_routes(d.entities, Order::Seed000, {}), {});
    const std::vector<std::string> rapids = lines_starting(g, {"G0 "});
    ASSERT_EQ(rapids.size(), 2u);
    EXPECT_EQ(rapids[0], "G0 X250.000 Y100.000");
    EXPECT_EQ(rapids[1], "G0 X275.000 Y200.000");
    EXPECT_EQ(lines_starting(g, {"G1 ", "G2 ", "G3 "}).size(), 19u);
    EXPECT_EQ(lines_starting(g, {"M3 S255"}).size(), 2u);
    EXPECT_EQ(lines_starting(g, {"M5"}).size(), 2u);
    // Arcs from Table 3.1's I and J: E9 (centre (200,125)) reversed runs clockwise from (200,100); E8 as drawn;
    // E14 (centre (250,187.5)) reversed from (200,225); the circle reversed.
    EXPECT_NE(g.find("G2 X175.000 Y125.000 I0.000 J25.000 F800\n"), std::string::npos) << g;
    EXPECT_NE(g.find("G3 X125.000 Y175.000 I-25.000 J0.000 F800\n"), std::string::npos) << g;
    EXPECT_NE(g.find("G3 X350.000 Y225.000 I50.000 J37.500 F800\n"), std::string::npos) << g;
    EXPECT_NE(g.find("G2 X250.000 Y250.000 I50.000 J-37.500 F800\n"), std::string::npos) << g;
    EXPECT_NE(g.find("G2 X275.000 Y200.000 I-25.000 J0.000 F800\n"), std::string::npos) << g;
    EXPECT_EQ(g.rfind("G21\nG90\nG17\nG94\n", 0), 0u);
    EXPECT_EQ(g.substr(g.size() - 4), "M30\n");
}

// The shipped job scenarios/compare/jobs/sample_drawing.nc is the same route written by hand from seed 000 §3.3 (with a
// return to the origin at its end): the interpreter reads the same moves from both.
TEST(CamSeed000, WorkedExampleMovesAreTheHandWrittenJobs) {
    const Drawing d = read_dxf(example_dxf(), {});
    std::istringstream ours(write_gcode(d.entities, order_routes(d.entities, Order::Seed000, {}), {}));
    const host::InterpreterOptions opt;
    const host::Program a = host::interpret(ours, "cam", opt);
    const host::Program b =
        host::interpret_file(std::string(CNC_SOURCE_DIR) + "/scenarios/compare/jobs/sample_drawing.nc", opt);
    ASSERT_EQ(a.moves.size() + 1, b.moves.size());
    for (std::size_t k = 0; k < a.moves.size(); ++k) {
        const host::ProgrammedMove& x = a.moves[k];
        const host::ProgrammedMove& y = b.moves[k];
        EXPECT_EQ(x.kind, y.kind) << "move " << k;
        EXPECT_NEAR(geom::distance(x.path.start, y.path.start), 0.0, 1e-9) << "move " << k;
        EXPECT_NEAR(geom::distance(x.path.end, y.path.end), 0.0, 1e-9) << "move " << k;
        if (x.path.is_arc) {
            EXPECT_NEAR(geom::distance(x.path.center, y.path.center), 0.0, 1e-9) << "move " << k;
            EXPECT_NEAR(x.path.sweep_rad, y.path.sweep_rad, 1e-9) << "move " << k;
        }
    }
}

// "On User Selection": the drawing's order, a rapid wherever an entity does not start where the last ended.
TEST(CamSeed000, SelectionKeepsTheDrawingOrder) {
    const Drawing d = read_dxf(example_dxf(), {});
    const std::vector<Route> routes = order_routes(d.entities, Order::Selection, {});
    int k = 0;
    for (const Route& r : routes) {
        for (const Step& s : r) {
            EXPECT_EQ(s.entity, k++);
            EXPECT_FALSE(s.reversed);
        }
    }
    // E0 -> E1 and on: only E10 -> E11 (250,125) and E15 -> E16 (25,225) meet in Table 3.1's order.
    EXPECT_EQ(routes.size(), 17u);
}

}  // namespace
}  // namespace cnc::cam
