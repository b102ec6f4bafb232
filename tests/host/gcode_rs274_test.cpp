// cncsim's moves and dwells against LinuxCNC's: each program of tests/data/rs274 with the canonical calls LinuxCNC's
// standalone interpreter printed for it (the command and version are in that folder's README).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/math_constants.hpp"
#include "host/core/gcode.hpp"

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

// The moving and waiting calls of an rs274 -g listing, in order: lines "  12 N..... CALL(ARGS)".
std::vector<Canon> linuxcnc_calls(const std::string& name) {
    std::ifstream in(data_path(name + ".canon"));
    EXPECT_TRUE(in) << name;
    std::vector<Canon> calls;
    for (std::string line; std::getline(in, line);) {
        const std::size_t dots = line.find("N..... ");
        const std::size_t open = line.find('(');
        if (dots == std::string::npos || open == std::string::npos || line.back() != ')') continue;
        Canon c{line.substr(dots + 7, open - dots - 7)};
        if (c.call != "STRAIGHT_TRAVERSE" && c.call != "STRAIGHT_FEED" && c.call != "ARC_FEED" && c.call != "DWELL") {
            continue;
        }
        const std::vector<double> n = numbers(line.substr(open + 1, line.size() - open - 2));
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
        calls.push_back(c);
    }
    return calls;
}

// The same calls made from cncsim's program: each wait before the move it precedes.
std::vector<Canon> cncsim_calls(const Program& p) {
    std::vector<Canon> calls;
    std::size_t w = 0;
    auto waits_before = [&](std::size_t move) {
        for (; w < p.waits.size() && p.waits[w].before_move == move; ++w) {
            EXPECT_EQ(p.waits[w].cause, WaitCause::Dwell) << "the programs have no Z-only move";
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

void expect_as_linuxcnc(const std::string& name) {
    const Program p = interpret_file(data_path(name + ".ngc"), {});
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

}  // namespace
}  // namespace cnc::host
