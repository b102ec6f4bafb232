// Every G-code input the interpreter rejects: the message names file:line and the offending word or problem.
#include <gtest/gtest.h>

#include "host_test_util.hpp"

namespace cnc::host {
namespace {

using test::bad_input_message;
using test::expect_bad_input;
using test::expect_gcode_error;
using test::run_gcode;

TEST(HostGcodeErrors, UnsupportedWordExactMessage) {
    EXPECT_EQ(bad_input_message([] { run_gcode("G1 X1 F100\nG41 X2\n"); }),
              "t.nc:2: unsupported word 'G41' (supported: G0 G1 G2 G3 G17 G20 G21 G90 G91 G92 G94 M2 M3 M5 M30 "
              "F I J R S N X Y)");
}

TEST(HostGcodeErrors, UnsupportedWords) {
    expect_gcode_error("G4 P1\n", {"t.nc:1:", "'G4'"});
    expect_gcode_error("M6\n", {"t.nc:1:", "'M6'"});
    expect_gcode_error("G0 X1\nT1\n", {"t.nc:2:", "'T1'"});
    expect_gcode_error("G1 X1 Z5 F100\n", {"t.nc:1:", "'Z5'"});
    expect_gcode_error("G0 A1\n", {"'A1'"});
    expect_gcode_error("G0 K1\n", {"'K1'"});
    expect_gcode_error("G91.1\n", {"'G91.1'"});
    expect_gcode_error("G18\n", {"'G18'"});
    expect_gcode_error("M4\n", {"'M4'"});
    expect_gcode_error("G-1\n", {"'G-1'"});
}

TEST(HostGcodeErrors, MalformedWords) {
    expect_gcode_error("G1 X F100\n", {"t.nc:1:", "word 'X' has no number"});
    expect_gcode_error("10 G1\n", {"t.nc:1:", "number '10' without a letter"});
    // Spaces are insignificant (RS274/NGC), so "G1 10" is the word G110.
    expect_gcode_error("G1 10\n", {"'G110'"});
    expect_gcode_error("G1 X1.2.3 F1\n", {"word 'X1.2.3' has a malformed number"});
    expect_gcode_error("G1 X--1 F1\n", {"word 'X--1' has a malformed number"});
    expect_gcode_error("G1 X1 # F1\n", {"t.nc:1:", "unexpected character '#'"});
    expect_gcode_error("%\n", {"unexpected character '%'"});
    expect_gcode_error("G1 X1 F1 )\n", {"unexpected character ')'"});
    expect_gcode_error("G0 X1\nG1 X2 (no end F100\n", {"t.nc:2:", "unterminated comment"});
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
    expect_gcode_error("G0 X10\nG2 X0 Y10.5 I-10 F100\n",
                       {"t.nc:2:", "G2 end point is not on the arc", "start radius 10.0000 mm", "end radius 10.5000 mm"});
    expect_gcode_error("G3 X10 R4 F100\n", {"t.nc:1:", "G3 radius 4.0000 mm is too small", "5.0000 mm"});
    expect_gcode_error("G2 R5 F100\n", {"t.nc:1:", "G2 with R needs an end point away from the start"});
    expect_gcode_error("G2 X10 R0 F100\n", {"R must not be 0"});
    expect_gcode_error("G2 X10 I5 R5 F100\n", {"either I/J or R"});
    expect_gcode_error("G2 I0 J0 F100\n", {"t.nc:1:", "arc radius is zero"});
    expect_gcode_error("G1 X10 I5 F100\n", {"t.nc:1:", "I, J and R are allowed only with G2/G3", "G1"});
}

TEST(HostGcodeErrors, MotionAndOriginProblems) {
    expect_gcode_error("G21\nX10\n", {"t.nc:2:", "X/Y without a motion mode"});
    expect_gcode_error("G92\n", {"t.nc:1:", "G92 needs X and/or Y"});
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
