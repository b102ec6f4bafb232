// Cutter radius compensation and tool offsets against geometry worked out here: the tool centre one radius from the
// programmed contour everywhere, the entry move, inside and outside corners, LinuxCNC's errors with their lines, the
// tool length offset in Z, and the tool table file's own errors. (The same programs' exact calls against LinuxCNC's
// are gcode_rs274_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "common/math_constants.hpp"
#include "host/core/tool_table.hpp"
#include "host_test_util.hpp"

namespace cnc::host {
namespace {

using test::expect_bad_input;

constexpr double kToolRadiusMm = 1.5;  // T1: the 3 mm tool
constexpr double kMicronMm = 1e-3;

std::shared_ptr<const ToolTable> tools() {
    std::istringstream in("T1 P1 D3.0 Z+0.5 ;3 mm end mill\nT2 P2 D6 Z-12.71\nT4 P4 D0 ;a laser: no radius\n");
    return std::make_shared<const ToolTable>(ToolTable::parse(in, "tools.tbl"));
}

Program run(const std::string& text) {
    InterpreterOptions opt;
    opt.tool_table = tools();
    return test::run_gcode(text, opt);
}

void expect_error(const std::string& text, std::initializer_list<std::string> parts) {
    expect_bad_input([&] { run(text); }, parts);
}

double segment_distance(geom::Vec2 p, geom::Vec2 a, geom::Vec2 b) {
    const double dx = b.x_mm - a.x_mm, dy = b.y_mm - a.y_mm;
    const double t = std::clamp(((p.x_mm - a.x_mm) * dx + (p.y_mm - a.y_mm) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return std::hypot(p.x_mm - (a.x_mm + t * dx), p.y_mm - (a.y_mm + t * dy));
}

// Points along a move, worked out here from its ends, centre and sweep.
std::vector<geom::Vec2> samples(const ProgrammedMove& m, int n = 64) {
    std::vector<geom::Vec2> pts;
    const geom::Segment& s = m.path;
    const double a0 = std::atan2(s.start.y_mm - s.center.y_mm, s.start.x_mm - s.center.x_mm);
    const double r = std::hypot(s.start.x_mm - s.center.x_mm, s.start.y_mm - s.center.y_mm);
    for (int k = 0; k <= n; ++k) {
        const double t = static_cast<double>(k) / n;
        if (s.is_arc) {
            const double a = a0 + t * s.sweep_rad;
            pts.push_back({s.center.x_mm + r * std::cos(a), s.center.y_mm + r * std::sin(a)});
        } else {
            pts.push_back(
                {s.start.x_mm + t * (s.end.x_mm - s.start.x_mm), s.start.y_mm + t * (s.end.y_mm - s.start.y_mm)});
        }
    }
    return pts;
}

// The moves of the compensated contour: after the entry line, before the G40 line.
std::vector<ProgrammedMove> contour_moves(const Program& p, int entry_line, int exit_line) {
    std::vector<ProgrammedMove> out;
    for (const ProgrammedMove& m : p.moves) {
        if (m.line > entry_line && m.line < exit_line) out.push_back(m);
    }
    return out;
}

void expect_continuous(const Program& p) {
    for (std::size_t i = 1; i < p.moves.size(); ++i) {
        EXPECT_NEAR(p.moves[i].path.start.x_mm, p.moves[i - 1].path.end.x_mm, 1e-9) << "move " << i;
        EXPECT_NEAR(p.moves[i].path.start.y_mm, p.moves[i - 1].path.end.y_mm, 1e-9) << "move " << i;
    }
}

// A 20 mm square, counter-clockwise from the middle of its bottom side round to it again; the entry comes square to
// that side from the tool's side (inside for G41, outside for G42), and the exit goes back.
std::string square(const char* side) {
    const std::string y = std::string(side) == "G41" ? "5" : "-5";
    return "G21 G90 G17\nT1 M6\nG0 X10 Y" + y + "\n" + side +
           " G1 X10 Y0 F600\nG1 X20 Y0\nG1 X20 Y20\nG1 X0 Y20\nG1 X0 Y0\nG1 X10 Y0\nG40 G1 X10 Y" + y + "\nM2\n";
}

double square_distance(geom::Vec2 p) {
    const geom::Vec2 c[] = {{0, 0}, {20, 0}, {20, 20}, {0, 20}};
    double d = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) d = std::min(d, segment_distance(p, c[k], c[(k + 1) % 4]));
    return d;
}

TEST(HostCutterComp, SquareToolCentreIsOneRadiusFromTheContour) {
    for (const char* side : {"G41", "G42"}) {
        SCOPED_TRACE(side);
        const Program p = run(square(side));
        expect_continuous(p);
        const std::vector<ProgrammedMove> moves = contour_moves(p, 4, 10);
        ASSERT_GE(moves.size(), 5u);
        for (const ProgrammedMove& m : moves) {
            for (const geom::Vec2 q : samples(m)) EXPECT_NEAR(square_distance(q), kToolRadiusMm, kMicronMm);
        }
    }
}

// Left of a counter-clockwise square is inside: the corners are concave, the offset lines meet 1.5 mm in.
TEST(HostCutterComp, InsideCornersAreWhereTheOffsetLinesMeet) {
    const Program p = run(square("G41"));
    const std::vector<ProgrammedMove> moves = contour_moves(p, 4, 10);  // the sides
    ASSERT_EQ(moves.size(), 5u);
    test::expect_point(moves[0].path.end, 20 - kToolRadiusMm, kToolRadiusMm);
    test::expect_point(moves[1].path.end, 20 - kToolRadiusMm, 20 - kToolRadiusMm);
    test::expect_point(moves[2].path.end, kToolRadiusMm, 20 - kToolRadiusMm);
    test::expect_point(moves[3].path.end, kToolRadiusMm, kToolRadiusMm);
    test::expect_point(moves[4].path.end, 10, kToolRadiusMm);
    for (const ProgrammedMove& m : moves) EXPECT_FALSE(m.path.is_arc);
}

// Right of it is outside: at each convex corner an arc of the tool radius about the programmed corner.
TEST(HostCutterComp, OutsideCornersGetAnArcAboutTheCorner) {
    const Program p = run(square("G42"));
    int arcs = 0;
    for (const ProgrammedMove& m : contour_moves(p, 4, 10)) {
        if (!m.path.is_arc) continue;
        ++arcs;
        EXPECT_NEAR(m.path.radius_mm(), kToolRadiusMm, 1e-9);
        EXPECT_NEAR(m.path.sweep_rad, kPi / 2.0, 1e-9);   // a quarter turn, counter-clockwise round each corner
        EXPECT_LT(square_distance(m.path.center), 1e-9);  // a corner of the square
        EXPECT_EQ(m.kind, MotionKind::ArcCCW);
    }
    EXPECT_EQ(arcs, 4);
    const ProgrammedMove& first_arc = p.moves[3];  // after the G0, the entry and the first side
    test::expect_point(first_arc.path.start, 20, -kToolRadiusMm);
    test::expect_point(first_arc.path.end, 20 + kToolRadiusMm, 0);
}

// The entry: a straight line from where the tool is to one radius beside the programmed end, square to the move
// (LinuxCNC); a concave corner after it cuts it back to where the next side's offset crosses.
TEST(HostCutterComp, EntryMoveEndsOneRadiusBesideItsEnd) {
    // Alone (G40 after it): from (-10, -8) toward (0, 0), ending left of the direction (10, 8).
    const Program alone = run("T1 M6\nG0 X-10 Y-8\nG41 G1 X0 Y0 F600\nG40 G1 X-10 Y-8\n");
    ASSERT_EQ(alone.moves.size(), 3u);
    const double len = std::hypot(10.0, 8.0);
    test::expect_point(alone.moves[1].path.start, -10, -8);
    test::expect_point(alone.moves[1].path.end, -8.0 / len * kToolRadiusMm, 10.0 / len * kToolRadiusMm);
    // Into the square from inside: down onto (10, 0) ends at (11.5, 0), cut back up to the bottom side's offset.
    const Program p = run(square("G41"));
    const ProgrammedMove& entry = p.moves[1];
    EXPECT_EQ(entry.line, 4);
    test::expect_point(entry.path.start, 10, 5);
    test::expect_point(entry.path.end, 10 + kToolRadiusMm, kToolRadiusMm);
    // The exit (G40) goes from the tool centre to the programmed point.
    test::expect_point(p.moves.back().path.start, 10, kToolRadiusMm);
    test::expect_point(p.moves.back().path.end, 10, 5);
}

TEST(HostCutterComp, CircleToolCentreIsOneRadiusFromTheCircle) {
    // Radius 10 about (20, 0): G3 with the tool left is inside (8.5), G2 with it left is outside (11.5).
    for (const char* arc : {"G3", "G2"}) {
        for (const char* side : {"G41", "G42"}) {
            SCOPED_TRACE(std::string(side) + " " + arc);
            // The entry runs along the circle's tangent at (30, 0), the way the arc goes.
            const std::string y = std::string(arc) == "G3" ? "-5" : "5";
            const Program p = run("G21 G17\nT1 M6\nG0 X30 Y" + y + "\n" + side + " G1 X30 Y0 F500\n" + arc +
                                  " X30 Y0 I-10 J0\nG40 G1 X30 Y" + y + "\nM2\n");
            expect_continuous(p);
            const std::vector<ProgrammedMove> moves = contour_moves(p, 4, 6);
            ASSERT_FALSE(moves.empty());
            double swept = 0.0;
            for (const ProgrammedMove& m : moves) {
                for (const geom::Vec2 q : samples(m)) {
                    EXPECT_NEAR(std::fabs(std::hypot(q.x_mm - 20.0, q.y_mm) - 10.0), kToolRadiusMm, kMicronMm);
                }
                swept += std::fabs(m.path.sweep_rad);
            }
            EXPECT_NEAR(swept, kTwoPi, 1e-9);  // the whole circle
            const bool inside = (std::string(side) == "G41") == (std::string(arc) == "G3");
            EXPECT_NEAR(moves.back().path.radius_mm(), inside ? 8.5 : 11.5, 1e-9);
        }
    }
}

// A tool of diameter 0 (G41 allowed, as LinuxCNC): the path is the programmed one.
TEST(HostCutterComp, ZeroRadiusOffsetsNothing) {
    const Program p = run("T4 M6\nG0 X0 Y0\nG41 G1 X10 Y0 F600\nG1 X10 Y10\nG40 G1 X0 Y0\n");
    ASSERT_EQ(p.moves.size(), 3u);  // the G0 from (0, 0) to (0, 0) is no move
    test::expect_point(p.moves[0].path.end, 10, 0);
    test::expect_point(p.moves[1].path.end, 10, 10);
}

// G41.1 / G42.1 D: the diameter on the line, no table entry.
TEST(HostCutterComp, DynamicCompTakesTheDiameter) {
    const Program p = run("G0 X0 Y-10\nG41.1 D4 G1 X0 Y0 F600\nG1 X0 Y10\nG40 G1 X5 Y20\n");
    // Going +Y with the tool on the left: x = -2.
    ASSERT_EQ(p.moves.size(), 4u);
    test::expect_point(p.moves[1].path.end, -2.0, 0.0);
    test::expect_point(p.moves[2].path.end, -2.0, 10.0);
}

TEST(HostCutterComp, ErrorsNameTheLineAsLinuxCnc) {
    expect_error("T1 M6\nG0 X0 Y0\nG41 G1 X1 Y0 F600\n",
                 {"t.nc:3: Length of cutter compensation entry move is not greater than the tool radius"});
    expect_error("T1 M6\nG0 X-10 Y0\nG41 G1 X0 Y0 F600\nG1 X10\nG3 X10 Y2 I0 J1\n",
                 {"t.nc:5: Tool radius not less than arc radius with comp"});
    // A slot narrower than the tool: the corner cuts the side before back past its start.
    expect_error("T1 M6\nG0 X-10 Y-10\nG41 G1 X0 Y0 F600\nG1 X20 Y0\nG1 X20 Y2\nG1 X0 Y2\n",
                 {"t.nc:6: Straight feed in concave corner cannot be reached by the tool without gouging"});
    expect_error("T1 M6\nG0 X-10 Y0\nG41 G1 X0 Y0 F600\nG42 G1 X10\n",
                 {"t.nc:4: Cannot turn cutter radius comp on when on"});
    expect_error("T1 M6\nG0 X-10 Y0\nG41 G1 X0 Y0 F600\nG41 G1 X10\n",
                 {"t.nc:4: Cannot turn cutter radius comp on when on"});
    expect_error("T1 M6\nG0 X-10 Y0\nG41 G1 X0 Y0 F600\nG40\nG2 X10 Y0 I5 J0\n",
                 {"t.nc:5: The move just after exiting cutter compensation mode must be straight, not an arc"});
    expect_error("T1 M6\nG41\nT2 M6\n", {"t.nc:3: Cannot change tools with cutter radius compensation on"});
    expect_error("T1 M6\nG41\nG43\n", {"t.nc:3: Cannot change tool offset with cutter radius compensation on"});
    expect_error("T1 M6\nG41\nG18\n", {"t.nc:3: Cannot change planes with cutter radius compensation on"});
    expect_error("T1 M6\nG41\nG55\n", {"t.nc:3: Cannot change coordinate systems with cutter radius compensation on"});
    expect_error("T1 M6\nG41\nG64 P0.1\n", {"t.nc:3: Cannot change control mode with cutter radius compensation on"});
    expect_error("T1 M6\nG41\nG92 X0\n", {"t.nc:3: Cannot change axis offsets with cutter radius comp"});
    expect_error("T1 M6\nG41\nG28\n", {"t.nc:3: Cannot use g28 or g30 with cutter radius comp"});
    expect_error("T1 M6\nG0 X-5 Y0\nG41 G1 X0 Y0 F600\nG53 G1 X10\n",
                 {"t.nc:4: Cannot use g53 with cutter radius comp"});
}

TEST(HostCutterComp, ToolWordsAndTheirErrors) {
    expect_error("T9 M6\n", {"t.nc:1: Requested tool 9 not found in the tool table (tools.tbl)"});
    expect_error("M6\n", {"t.nc:1: Need tool prepared -Txx- for toolchange"});
    expect_error("G41 D7\n", {"t.nc:1: Requested tool 7 not found in the tool table"});
    expect_error("G1 X1 D1 F100\n", {"t.nc:1: D word with no G41, G41.1, G42 or G42.1 to use it"});
    expect_error("G0 X1 H1\n", {"t.nc:1: H word with no G43 or G43.2 to use it"});
    expect_error("G41.1 G1 X10 F100\n", {"t.nc:1: G41.1 with no D word"});
    expect_error("M61\n", {"t.nc:1: Need non-negative Q-word to specify tool number with M61"});
    expect_error("T1.5\n", {"t.nc:1: T must be a whole number >= 0"});
}

// G43 H2: the tool tip goes to the programmed Z, so the machine (spindle) Z is Z + T2's -12.71; G49 cancels it.
TEST(HostCutterComp, ToolLengthOffsetMovesZByTheTablesValue) {
    const Program p = run("T2 M6 G43 H2\nG1 X10 Z1 F600\nG49\nG1 X20 Z1\nM61 Q1 G43\nG1 X30\nG1 X40 Z1\n");
    ASSERT_EQ(p.moves.size(), 4u);
    EXPECT_NEAR(p.moves[0].z_end_mm, 1.0 - 12.71, 1e-9);
    EXPECT_NEAR(p.moves[1].z_end_mm, 1.0, 1e-9);
    EXPECT_NEAR(p.moves[2].z_end_mm, 1.0, 1e-9);  // G43 alone moves nothing
    EXPECT_NEAR(p.moves[3].z_end_mm, 1.5, 1e-9);  // M61 Q1 and G43: T1's +0.5
}

// Without a tool table the words are ignored and listed, as before: nothing is offset.
TEST(HostCutterComp, WithoutToolTableTheWordsAreIgnored) {
    const Program p = test::run_gcode("T1 M6\nG0 X-10 Y0\nG41 D1 G1 X0 Y0 F600\nG1 X10\nG43 H1\nG40 G49\n");
    ASSERT_EQ(p.moves.size(), 3u);
    test::expect_point(p.moves[2].path.end, 10, 0);
    std::vector<std::string> words;
    for (const IgnoredWord& w : p.ignored) words.push_back(w.word);
    EXPECT_EQ(words, (std::vector<std::string>{"T1", "M6", "G41", "D1", "G43", "H1", "G40", "G49"}));
}

TEST(HostToolTable, ReadsLinuxCncLines) {
    std::istringstream in("; a comment line\n\nT1 P1 D3.0 Z+0.5 ;3 mm\nt7 p3 x0 y0 z-1.25 d0.8 i0 j0 q0\n");
    const ToolTable t = ToolTable::parse(in, "t.tbl");
    ASSERT_EQ(t.size(), 2u);
    EXPECT_DOUBLE_EQ(t.find(1)->diameter_mm, 3.0);
    EXPECT_DOUBLE_EQ(t.find(1)->z_offset_mm, 0.5);
    EXPECT_EQ(t.find(7)->pocket, 3);
    EXPECT_DOUBLE_EQ(t.find(7)->z_offset_mm, -1.25);
    EXPECT_EQ(t.find(7)->line, 4);
    EXPECT_EQ(t.find(2), nullptr);
    EXPECT_DOUBLE_EQ(t.find(0)->diameter_mm, 0.0);  // tool 0: no tool
}

TEST(HostToolTable, BadLinesNameFileLineAndWhatIsAllowed) {
    auto expect_table_error = [](const std::string& text, std::initializer_list<std::string> parts) {
        expect_bad_input(
            [&] {
                std::istringstream in(text);
                ToolTable::parse(in, "t.tbl");
            },
            parts);
    };
    expect_table_error("T1 D3\nP2 D4\n", {"t.tbl:2: no T word", "T<tool>"});
    expect_table_error("T1 D3 K4\n", {"t.tbl:1: 'K4' is not a tool-table word", "D<diameter mm>"});
    expect_table_error("T1 D\n", {"t.tbl:1: 'D': the letter is not followed by a number"});
    expect_table_error("T1 D 3\n", {"t.tbl:1: 'D': the letter is not followed by a number"});
    expect_table_error("T1.5 D3\n", {"t.tbl:1: 'T1.5' must be a whole number 1 .."});
    expect_table_error("T0 D3\n", {"t.tbl:1: 'T0' must be a whole number 1 .."});
    expect_table_error("T1 D3 D4\n", {"t.tbl:1: the letter D appears twice"});
    expect_table_error("T1 D3\nT1 D4\n", {"t.tbl:2: tool 1 is already on line 1"});
    expect_bad_input([] { ToolTable::load("/nonexistent/t.tbl"); }, {"/nonexistent/t.tbl: cannot open the tool table"});
}

}  // namespace
}  // namespace cnc::host
