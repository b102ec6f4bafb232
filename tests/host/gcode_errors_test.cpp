// Every G-code input the interpreter rejects: the message names file:line and the offending word or problem.
#include <gtest/gtest.h>

#include "host_test_util.hpp"

namespace cnc::host {
namespace {

using test::bad_input_message;
using test::expect_bad_input;
using test::expect_gcode_error;
using test::run_gcode;

TEST(HostGcodeErrors, UnsupportedWordNamesTheLineAndTheWordTable) {
    const std::string msg = bad_input_message([] { run_gcode("G1 X1 F100\nG33 X2 K1\n"); });
    EXPECT_EQ(msg.rfind("t.nc:2: unsupported word 'G33'\n", 0), 0u) << msg;
    EXPECT_NE(msg.find("t.nc:2: unsupported word 'K1'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("docs/gcode.md"), std::string::npos) << msg;
}

TEST(HostGcodeErrors, UnsupportedWords) {
    expect_gcode_error("G33 X1\n", {"t.nc:1:", "'G33'"});
    expect_gcode_error("G0 X1\nG81 X1 Y1 Z-1 R1\n", {"t.nc:2:", "'G81'"});
    expect_gcode_error("G0 K1\n", {"'K1'"});
    expect_gcode_error("G0 B1\n", {"'B1'"});
    expect_gcode_error("M84\n", {"'M84'"});
    expect_gcode_error("M200\n", {"'M200'"});
    expect_gcode_error("G95\n", {"'G95'"});
    expect_gcode_error("G-1\n", {"'G-1'"});
    expect_gcode_error("G1.25\n", {"'G1.25'"});
    expect_gcode_error("o100 sub\n", {"t.nc:1:", "'O100SUB'"});
    expect_gcode_error("#1 = 10\nG1 X#1 F1\n", {"t.nc:1:", "unsupported word '#'", "2 lines: 1, 2"});
    expect_gcode_error("G1 X[1+2] F1\n", {"t.nc:1:", "unsupported word '[...]'"});
}

TEST(HostGcodeErrors, EveryUnsupportedWordOfTheFileAtOnce) {
    const std::string msg = bad_input_message([] { run_gcode("G33 X1\nG1 X2 F10\nG33 X3\nM84\nG2 X1\nG81\n"); });
    EXPECT_NE(msg.find("t.nc:1: unsupported word 'G33' (2 lines: 1, 3)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("t.nc:4: unsupported word 'M84'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("t.nc:6: unsupported word 'G81'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("t.nc:5: G2 needs I/J"), std::string::npos) << msg;
}

TEST(HostGcodeErrors, StrictPolicyRefusesEveryIgnoredWordWithItsLines) {
    InterpreterOptions opt;
    opt.policy = GcodePolicy::Strict;
    const std::string msg = bad_input_message([&] { run_gcode("%\nT1 M6\nG40 G1 X1 F10\nT1\n/G1 X5\n%\n", opt); });
    EXPECT_EQ(msg.rfind("t.nc:1: not executed by this machine", 0), 0u) << msg;
    EXPECT_NE(msg.find("'%'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("t.nc:2: not executed by this machine (strict policy; tool select: the machine has one tool) "
                       "'T1' (2 lines: 2, 4)"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("'M6'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("t.nc:3:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'G40'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("t.nc:5:"), std::string::npos) << msg;
}

TEST(HostGcodeErrors, MalformedWords) {
    expect_gcode_error("G1 X F100\n", {"t.nc:1:", "word 'X' has no number"});
    expect_gcode_error("10 G1\n", {"t.nc:1:", "number '10' without a letter"});
    // Spaces are insignificant (RS274/NGC), so "G1 10" is the word G110.
    expect_gcode_error("G1 10\n", {"'G110'"});
    expect_gcode_error("G1 X1.2.3 F1\n", {"word 'X1.2.3' has a malformed number"});
    expect_gcode_error("G1 X--1 F1\n", {"word 'X--1' has a malformed number"});
    expect_gcode_error("G1 X1 $ F1\n", {"t.nc:1:", "unexpected character '$'"});
    expect_gcode_error("G1 X1 F1 %\n", {"unexpected character '%'"});
    expect_gcode_error("G1 X1 F1 )\n", {"unexpected character ')'"});
    expect_gcode_error("G0 X1\nG1 X2 (no end F100\n", {"t.nc:2:", "unterminated comment"});
    expect_gcode_error("G0 X1 (outer (inner) )\n", {"t.nc:1:", "nested comment"});
}

// A number beyond a double (1.8e308: IEEE 754 binary64) is out of range, whether written with an exponent (which
// G-code does not have: "1e5" reads as 1 and the word E5) or with 400 digits; in range, "e" stays the E word.
TEST(HostGcodeErrors, NumbersOutOfRange) {
    expect_gcode_error("G1 X1e400 F100\n", {"t.nc:1:", "number '1e400' is out of range"});
    expect_gcode_error("G1 X-2.5E+999 F100\n", {"number '-2.5E+999' is out of range"});
    expect_gcode_error("G1 X1e-400 F100\n", {"number '1e-400' is out of range"});
    expect_gcode_error("G1 X1" + std::string(400, '0') + " F100\n", {"t.nc:1:", "the number is out of range"});
    const Program p = run_gcode("G1 X1e5 F100\n");
    ASSERT_EQ(p.moves.size(), 1u);
    EXPECT_DOUBLE_EQ(p.moves[0].path.end.x_mm, 1.0);
}

// Control bytes of a job are quoted escaped (common/printable.hpp), not sent to the terminal.
TEST(HostGcodeErrors, ControlBytesAreEscapedInMessages) {
    expect_gcode_error("G1 X1 \x1b[2J F1\n", {"t.nc:1:", "unexpected character '\\x1B'"});
}

TEST(HostGcodeErrors, ConflictingAndRepeatedWords) {
    expect_gcode_error("G0 G1 X1 F1\n", {"t.nc:1:", "'G1' conflicts", "motion"});
    expect_gcode_error("G90 G91\n", {"'G91' conflicts", "distance"});
    expect_gcode_error("G20 G21\n", {"'G21' conflicts", "units"});
    expect_gcode_error("M3 M5\n", {"'M5' conflicts", "laser"});
    expect_gcode_error("G1 X1 X2 F1\n", {"word 'X' appears twice"});
    expect_gcode_error("G1 X1 F1 F2\n", {"word 'F' appears twice"});
}

TEST(HostGcodeErrors, FeedProblems) {
    expect_gcode_error("G0 X1\nG1 X2\n", {"t.nc:2:", "G1 needs a feed rate"});
    expect_gcode_error("G2 X2 I1\n", {"t.nc:1:", "G2 needs a feed rate"});
    expect_gcode_error("G1 X1 F0\n", {"t.nc:1:", "feed must be > 0", "'F0'"});
    expect_gcode_error("G1 X1 F-5\n", {"feed must be > 0", "'F-5'"});
}

TEST(HostGcodeErrors, ArcProblems) {
    expect_gcode_error("G1 F100\nG2 X10 Y0\n", {"t.nc:2:", "G2 needs I/J", "or R"});
    expect_gcode_error("G0 X10\nG2 X0 Y10.5 I-10 F100\n", {"t.nc:2:", "G2 end point is not on the arc",
                                                           "start radius 10.0000 mm", "end radius 10.5000 mm"});
    expect_gcode_error("G3 X10 R4 F100\n", {"t.nc:1:", "G3 radius 4.0000 mm is too small", "5.0000 mm"});
    expect_gcode_error("G2 R5 F100\n", {"t.nc:1:", "G2 with R needs an end point away from the start"});
    expect_gcode_error("G2 X10 R0 F100\n", {"R must not be 0"});
    expect_gcode_error("G2 X10 I5 R5 F100\n", {"either I/J or R"});
    expect_gcode_error("G2 I0 J0 F100\n", {"t.nc:1:", "arc radius is zero"});
    expect_gcode_error("G1 X10 I5 F100\n", {"t.nc:1:", "I, J and R are allowed only with G2/G3", "G1"});
}

TEST(HostGcodeErrors, MotionAndOriginProblems) {
    expect_gcode_error("G21\nX10\n", {"t.nc:2:", "axis words without a motion mode"});
    expect_gcode_error("G92\n", {"t.nc:1:", "G92 needs X, Y and/or Z"});
    expect_gcode_error("G92 G1 X1 F100\n", {"G92 and G1 on the same line"});
    expect_gcode_error("G92 X1 I1\n", {"I, J and R are allowed only with G2/G3"});
}

TEST(HostGcodeErrors, ErrorAfterProgramEndIsNotReported) {
    EXPECT_NO_THROW(run_gcode("M2\nG41\n"));
}

TEST(HostGcodeErrors, BadRapidFeedOption) {
    InterpreterOptions opt;
    opt.rapid_feed_mm_per_min = 0.0;
    expect_bad_input([&] { run_gcode("G0 X1\n", opt); }, {"t.nc:", "rapid feed must be > 0"});
}

TEST(HostGcodeErrors, MissingFile) {
    expect_bad_input([] { interpret_file("/nonexistent/job.nc", {}); },
                     {"/nonexistent/job.nc:", "cannot open G-code file"});
}

}  // namespace
}  // namespace cnc::host
