// cncsim's moves and dwells against LinuxCNC's: each program of tests/data/rs274 with the canonical calls LinuxCNC's
// standalone interpreter printed for it (the command and version are in that folder's README). The cutter
// compensation and tool length programs run with the folder's tool table (tools.tbl; rs274 read tools_in.tbl, the
// same tools in inches), and the error programs against the message rs274 stopped with.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "common/math_constants.hpp"
#include "host/core/gcode.hpp"
#include "host/core/tool_table.hpp"
#include "host_test_util.hpp"

namespace cnc::host {
namespace {

// rs274 prints 4 decimals.
constexpr double kPrintedMm = 0.5e-4;

// One canonical call that moves the tool or waits.
struct Canon {
    std::string call;  // STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED, DWELL
    double x = 0.0, y = 0.0, z = 0.0;
    double cx = 0.0, cy = 0.0;
    int rotation = 0;  // ARC_FEED: + counter-clockwise, - clockwise; the magnitude counts the turns
    double seconds = 0.0;
};

std::string data_path(const std::string& name) {
    return std::string(CNC_SOURCE_DIR) + "/tests/data/rs274/" + name;
}

std::vector<double> numbers(const std::string& args) {
    std::vector<double> v;
    std::stringstream ss(args);
    for (std::string item; std::getline(ss, item, ',');) v.push_back(std::stod(item));
    return v;
}

// X Y Z of a canonical offset.
struct Offset {
    double x = 0.0, y = 0.0, z = 0.0;
};

// The moving and waiting calls of an rs274 -g listing, in order: lines "  12 N..... CALL(ARGS)". Their coordinates
// are the program's; the machine's add the work offsets (SET_G5X_OFFSET, SET_G92_OFFSET) and, for Z, the tool length
// offset in force (USE_TOOL_LENGTH_OFFSET), which is what cncsim's moves give.
std::vector<Canon> linuxcnc_calls(const std::string& name) {
    std::ifstream in(data_path(name + ".canon"));
    EXPECT_TRUE(in) << name;
    std::vector<Canon> calls;
    Offset g5x, g92, tool;
    double last_x = 0.0, last_y = 0.0;
    for (std::string line; std::getline(in, line);) {
        const std::size_t dots = line.find("N..... ");
        const std::size_t open = line.find('(');
        if (dots == std::string::npos || open == std::string::npos || line.back() != ')') continue;
        Canon c{line.substr(dots + 7, open - dots - 7)};
        const std::string args = line.substr(open + 1, line.size() - open - 2);
        if (c.call == "SET_G5X_OFFSET") {
            const std::vector<double> n = numbers(args);  // system, x, y, z, ...
            g5x = {n.at(1), n.at(2), n.at(3)};
        } else if (c.call == "SET_G92_OFFSET") {
            const std::vector<double> n = numbers(args);
            g92 = {n.at(0), n.at(1), n.at(2)};
        } else if (c.call == "USE_TOOL_LENGTH_OFFSET") {
            std::istringstream xyz(args.substr(0, args.find(',')));  // "x y z, a b c, u v w"
            xyz >> tool.x >> tool.y >> tool.z;
        }
        if (c.call != "STRAIGHT_TRAVERSE" && c.call != "STRAIGHT_FEED" && c.call != "ARC_FEED" && c.call != "DWELL") {
            continue;
        }
        const std::vector<double> n = numbers(args);
        if (c.call == "DWELL") {
            c.seconds = n.at(0);
        } else if (c.call == "ARC_FEED") {
            // first end, second end, first centre, second centre, rotation, axis end (Z in G17), a, b, c
            c.x = n.at(0), c.y = n.at(1), c.cx = n.at(2), c.cy = n.at(3);
            c.rotation = static_cast<int>(n.at(4));
            c.z = n.at(5);
        } else {
            c.x = n.at(0), c.y = n.at(1), c.z = n.at(2);
        }
        if (c.call != "DWELL") {
            c.x += g5x.x + g92.x, c.y += g5x.y + g92.y, c.z += g5x.z + g92.z + tool.z;
            c.cx += g5x.x + g92.x, c.cy += g5x.y + g92.y;
            // A move of Z alone is host dead time in cncsim (a wait, not a move): its Z shows in the next move's.
            const bool z_only = c.call != "ARC_FEED" && c.x == last_x && c.y == last_y;
            last_x = c.x, last_y = c.y;
            if (z_only) continue;
        }
        calls.push_back(c);
    }
    return calls;
}

// The folder's tool table, in millimetres: the tools of tools_in.tbl, which rs274 read in inches.
InterpreterOptions with_tools() {
    InterpreterOptions opt;
    opt.tool_table = std::make_shared<const ToolTable>(ToolTable::load(data_path("tools.tbl")));
    return opt;
}

// The same calls made from cncsim's program: each wait before the move it precedes.
std::vector<Canon> cncsim_calls(const Program& p) {
    std::vector<Canon> calls;
    std::size_t w = 0;
    auto waits_before = [&](std::size_t move) {
        for (; w < p.waits.size() && p.waits[w].before_move == move; ++w) {
            if (p.waits[w].cause == WaitCause::OtherAxes) continue;  // a Z move (left out of rs274's calls too)
            calls.push_back(Canon{"DWELL", 0, 0, 0, 0, 0, 0, p.waits[w].seconds});
        }
    };
    for (std::size_t i = 0; i < p.moves.size(); ++i) {
        waits_before(i);
        const ProgrammedMove& m = p.moves[i];
        Canon c{m.kind == MotionKind::Rapid ? "STRAIGHT_TRAVERSE" : m.path.is_arc ? "ARC_FEED" : "STRAIGHT_FEED"};
        c.x = m.path.end.x_mm, c.y = m.path.end.y_mm, c.z = m.z_end_mm;
        if (m.path.is_arc) {
            c.cx = m.path.center.x_mm, c.cy = m.path.center.y_mm;
            const int turns = static_cast<int>(std::ceil(std::fabs(m.path.sweep_rad) / kTwoPi - 1e-9));
            c.rotation = m.path.sweep_rad > 0.0 ? turns : -turns;
        }
        calls.push_back(c);
    }
    waits_before(p.moves.size());
    return calls;
}

void expect_as_linuxcnc(const std::string& name, const InterpreterOptions& opt = {}) {
    const Program p = interpret_file(data_path(name + ".ngc"), opt);
    const std::vector<Canon> want = linuxcnc_calls(name);
    const std::vector<Canon> got = cncsim_calls(p);
    ASSERT_EQ(got.size(), want.size()) << name;
    for (std::size_t i = 0; i < want.size(); ++i) {
        SCOPED_TRACE(name + " call " + std::to_string(i) + " " + want[i].call);
        EXPECT_EQ(got[i].call, want[i].call);
        EXPECT_NEAR(got[i].x, want[i].x, kPrintedMm);
        EXPECT_NEAR(got[i].y, want[i].y, kPrintedMm);
        EXPECT_NEAR(got[i].z, want[i].z, kPrintedMm);
        EXPECT_NEAR(got[i].cx, want[i].cx, kPrintedMm);
        EXPECT_NEAR(got[i].cy, want[i].cy, kPrintedMm);
        EXPECT_EQ(got[i].rotation, want[i].rotation);
        EXPECT_NEAR(got[i].seconds, want[i].seconds, kPrintedMm);
    }
}

// `G04 P.001 G0 X1.0 Y1.0 S1000 M3`: the dwell, then the rapid; S beside G4 P is the spindle (laser) power.
TEST(GcodeAsLinuxCnc, G4BesideAMotionDwellsFirst) {
    expect_as_linuxcnc("g4_beside_motion");
    const Program p = interpret_file(data_path("g4_beside_motion.ngc"), {});
    ASSERT_FALSE(p.moves.empty());
    EXPECT_EQ(p.moves.front().power_s, 1000.0);
}

// G3 P2 about a full circle: two turns; a helical G2 P3: three turns, Z spread over them; P1: the plain arc.
TEST(GcodeAsLinuxCnc, ArcPMakesTheTurns) {
    expect_as_linuxcnc("arc_turns");
    const Program p = interpret_file(data_path("arc_turns.ngc"), {});
    ASSERT_EQ(p.moves.size(), 4u);
    EXPECT_NEAR(p.moves[1].path.length_mm(), 2.0 * kTwoPi * 10.0, 1e-9);
    // Half a circle of radius 5 and two more turns.
    EXPECT_NEAR(p.moves[2].path.length_mm(), (0.5 + 2.0) * kTwoPi * 5.0, 1e-9);
}

// Lines ending in CR CR LF: one line end each, so the moves and their line numbers are LinuxCNC's.
TEST(GcodeAsLinuxCnc, CrCrLfIsOneLineEnd) {
    expect_as_linuxcnc("cr_cr_lf");
    const Program p = interpret_file(data_path("cr_cr_lf.ngc"), {});
    ASSERT_EQ(p.moves.size(), 3u);
    EXPECT_EQ(p.moves[0].line, 3);
    EXPECT_EQ(p.moves[2].line, 5);
    EXPECT_EQ(p.lines, 6);
}

// rs274's error for a program it stopped on: the message line, then the text of the line it stopped at.
struct LinuxCncError {
    std::string message;
    int line = 0;  // 1-based, in the .ngc
};

LinuxCncError linuxcnc_error(const std::string& name) {
    std::vector<std::string> program;
    std::ifstream ngc(data_path(name + ".ngc"));
    for (std::string line; std::getline(ngc, line);) program.push_back(line);
    std::ifstream in(data_path(name + ".canon"));
    std::string previous;
    for (std::string line; std::getline(in, line);) {
        for (std::size_t k = 0; k < program.size(); ++k) {
            if (line == program[k] && !previous.empty()) return {previous, static_cast<int>(k) + 1};
        }
        if (line.find("N..... ") == std::string::npos && line != "executing") previous = line;
    }
    ADD_FAILURE() << name << ": no error in the rs274 listing";
    return {};
}

// cncsim refuses the program with LinuxCNC's message, naming the line rs274 stopped at.
void expect_error_as_linuxcnc(const std::string& name) {
    const LinuxCncError want = linuxcnc_error(name);
    ASSERT_FALSE(want.message.empty());
    const std::string path = data_path(name + ".ngc");
    test::expect_bad_input([&] { interpret_file(path, with_tools()); },
                           {path + ":" + std::to_string(want.line) + ": " + want.message});
}

// G41 inside a square: the entry move square to its end, the arc round the first corner (convex against the entry),
// the inside corners where the offset lines meet, the exit from the tool centre.
TEST(GcodeAsLinuxCnc, CutterCompInsideASquare) {
    expect_as_linuxcnc("comp_square_g41", with_tools());
}

// G42 outside the same square: an arc about each programmed corner.
TEST(GcodeAsLinuxCnc, CutterCompOutsideASquareRoundsTheCorners) {
    expect_as_linuxcnc("comp_square_g42", with_tools());
}

// A circle inside with the 3 mm tool (radius 10 - 1.5), then outside with the 6 mm tool after M6 (10 + 3).
TEST(GcodeAsLinuxCnc, CutterCompCircles) {
    expect_as_linuxcnc("comp_circles", with_tools());
}

// Lines and arcs: a tangent arc, a Z move and a dwell held behind the open move, concave line-arc, arc-arc and
// arc-line corners, a helix, a rapid under compensation, G42.1 with D the diameter, R arcs.
TEST(GcodeAsLinuxCnc, CutterCompLinesAndArcs) {
    expect_as_linuxcnc("comp_mixed", with_tools());
}

// An arc as the entry move (G42 G2, then G41 D2 G3 with the other tool's radius).
TEST(GcodeAsLinuxCnc, CutterCompEntryArc) {
    expect_as_linuxcnc("comp_entry_arc", with_tools());
}

// G43 (the tool in the spindle), G43 H1, G43.1 Z, G43.2 H, G49, G43 H0 and G92 with an offset in force: machine Z
// is the program's plus the offset.
TEST(GcodeAsLinuxCnc, ToolLengthOffsetsMoveZ) {
    expect_as_linuxcnc("tool_length", with_tools());
    const Program p = interpret_file(data_path("tool_length.ngc"), with_tools());
    ASSERT_FALSE(p.moves.empty());
    ASSERT_EQ(p.moves.size(), 8u);
    EXPECT_NEAR(p.moves[0].z_end_mm, 5.0 - 12.71, 1e-9);  // G0 X1 Z5 under T2's G43: -12.71
    EXPECT_NEAR(p.moves[3].z_end_mm, -1.0 + 0.5, 1e-9);   // G1 X20 Z-1 under G43 H1: +0.5
    EXPECT_NEAR(p.moves[6].z_end_mm, 5.0, 1e-9);          // G0 X23 Z5 under G49
}

TEST(GcodeAsLinuxCnc, CutterCompErrorsAreLinuxCncs) {
    for (const char* name :
         {"comp_err_concave_line", "comp_err_concave_arc", "comp_err_small_arc", "comp_err_on_when_on",
          "comp_err_short_entry", "comp_err_arc_after_g40", "comp_err_tool_change"}) {
        SCOPED_TRACE(name);
        expect_error_as_linuxcnc(name);
    }
}

}  // namespace
}  // namespace cnc::host
