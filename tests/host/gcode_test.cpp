#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "host_test_util.hpp"
#include "support/test_path.hpp"

namespace cnc::host {
namespace {

using test::expect_point;
using test::kEps;
using test::run_gcode;

TEST(HostGcode, SeedSampleRectangle) {
    // seed 000 §2.2 (Table 2.1 and its sample program): 40 x 20 mm rectangle from (10,10).
    const Program p = run_gcode(
        "G21\nG90\nG17\nG94\nG0 X10.000 Y10.000\nM3 S255\nG1 X50.000 Y10.000 F800\nG1 X50.000 Y30.000 F800\n"
        "G1 X10.000 Y30.000 F800\nG1 X10.000 Y10.000 F800\nM5\nM30\n");
    EXPECT_EQ(p.filename, "t.nc");
    ASSERT_EQ(p.moves.size(), 5u);
    EXPECT_EQ(p.moves[0].kind, MotionKind::Rapid);
    EXPECT_DOUBLE_EQ(p.moves[0].feed_mm_per_min, 1200.0);
    EXPECT_FALSE(p.moves[0].laser_on);
    EXPECT_EQ(p.moves[0].line, 5);
    expect_point(p.moves[0].path.start, 0, 0);
    expect_point(p.moves[0].path.end, 10, 10);
    for (int i = 1; i < 5; ++i) {
        EXPECT_EQ(p.moves[i].kind, MotionKind::Linear);
        EXPECT_DOUBLE_EQ(p.moves[i].feed_mm_per_min, 800.0);
        EXPECT_TRUE(p.moves[i].laser_on);
        EXPECT_EQ(p.moves[i].line, 6 + i);
        EXPECT_FALSE(p.moves[i].path.is_arc);
    }
    expect_point(p.moves[1].path.end, 50, 10);
    expect_point(p.moves[2].path.end, 50, 30);
    expect_point(p.moves[4].path.start, 10, 30);
    expect_point(p.moves[4].path.end, 10, 10);
}

TEST(HostGcode, RelativeMoves) {
    const Program p = run_gcode("G91\nG0 X5 Y5\nG1 X-2 Y3 F100\nG1 Y-1\nG90 G1 X0 Y0\n");
    ASSERT_EQ(p.moves.size(), 4u);
    expect_point(p.moves[0].path.end, 5, 5);
    expect_point(p.moves[1].path.end, 3, 8);
    expect_point(p.moves[2].path.end, 3, 7);
    expect_point(p.moves[3].path.end, 0, 0);
}

TEST(HostGcode, InchScalesCoordinatesArcWordsAndFeed) {
    const Program p = run_gcode("G20\nG1 X1 Y0.5 F10\nG2 X2 Y0.5 R0.5\nG21 G1 X0 Y0\n");
    ASSERT_EQ(p.moves.size(), 3u);
    expect_point(p.moves[0].path.end, 25.4, 12.7);
    EXPECT_DOUBLE_EQ(p.moves[0].feed_mm_per_min, 254.0);
    EXPECT_NEAR(p.moves[1].path.radius_mm(), 12.7, kEps);
    expect_point(p.moves[1].path.end, 50.8, 12.7);
    // The feed keeps its physical value after G21.
    EXPECT_DOUBLE_EQ(p.moves[2].feed_mm_per_min, 254.0);
}

TEST(HostGcode, InchModeOnTheSameLineAppliesToThatLine) {
    const Program p = run_gcode("G1 X1 F10 G20\n");
    ASSERT_EQ(p.moves.size(), 1u);
    expect_point(p.moves[0].path.end, 25.4, 0);
    EXPECT_DOUBLE_EQ(p.moves[0].feed_mm_per_min, 254.0);
}

TEST(HostGcode, G92OffsetsLaterCoordinatesPathStaysInMachineCoordinates) {
    const Program p = run_gcode("G0 X10 Y10\nG92 X0 Y0\nG1 X5 F100\nG92 Y100\nG1 Y101\nG91 G92 X1\nG90 G1 X2\n");
    ASSERT_EQ(p.moves.size(), 4u);
    expect_point(p.moves[1].path.end, 15, 10);
    expect_point(p.moves[2].path.end, 15, 11);
    // G92 X1 at machine X15 (absolute even in G91): program X2 = machine X16.
    expect_point(p.moves[3].path.end, 16, 11);
}

TEST(HostGcode, G92InInchUnits) {
    const Program p = run_gcode("G0 X10\nG20 G92 X0\nG0 X1\n");
    ASSERT_EQ(p.moves.size(), 2u);
    expect_point(p.moves[1].path.end, 35.4, 0);
}

TEST(HostGcode, ArcWithCentreOffsets) {
    const Program p = run_gcode("G0 X10 Y0\nG3 X0 Y10 I-10 J0 F100\nG0 X10 Y0\nG2 X0 Y10 I-10 F100\n");
    ASSERT_EQ(p.moves.size(), 4u);
    const geom::Segment& ccw = p.moves[1].path;
    EXPECT_EQ(p.moves[1].kind, MotionKind::ArcCCW);
    EXPECT_TRUE(ccw.is_arc);
    expect_point(ccw.center, 0, 0);
    EXPECT_NEAR(ccw.sweep_rad, M_PI / 2, kEps);
    expect_point(ccw.end, 0, 10);
    const geom::Segment& cw = p.moves[3].path;
    EXPECT_EQ(p.moves[3].kind, MotionKind::ArcCW);
    EXPECT_NEAR(cw.sweep_rad, -1.5 * M_PI, kEps);
    EXPECT_NEAR(cw.length_mm(), 15 * M_PI, 1e-9);
}

TEST(HostGcode, ArcEndWithinToleranceKeepsProgrammedEnd) {
    // End radius 10.005 vs start radius 10: inside the 0.01 mm tolerance.
    const Program p = run_gcode("G0 X10\nG3 X0 Y10.005 I-10 F100\nG1 X0 Y0\n");
    ASSERT_EQ(p.moves.size(), 3u);
    expect_point(p.moves[1].path.end, 0, 10.005);
    expect_point(p.moves[2].path.start, 0, 10.005);
}

TEST(HostGcode, RadiusFormShortAndLongArcs) {
    const double h = std::sqrt(100.0 - 25.0);
    const Program p = run_gcode(
        "G2 X10 Y0 R10 F100\nG0 X0 Y0\nG2 X10 Y0 R-10\nG0 X0 Y0\nG3 X10 Y0 R10\nG0 X0 Y0\nG3 X10 Y0 R-10\n"
        "G0 X0 Y0\nG2 X10 Y0 R5\n");
    ASSERT_EQ(p.moves.size(), 9u);
    const geom::Segment& cw_short = p.moves[0].path;
    expect_point(cw_short.center, 5, -h);
    EXPECT_NEAR(cw_short.sweep_rad, -M_PI / 3, kEps);
    const geom::Segment& cw_long = p.moves[2].path;
    expect_point(cw_long.center, 5, h);
    EXPECT_NEAR(cw_long.sweep_rad, -5 * M_PI / 3, kEps);
    const geom::Segment& ccw_short = p.moves[4].path;
    expect_point(ccw_short.center, 5, h);
    EXPECT_NEAR(ccw_short.sweep_rad, M_PI / 3, kEps);
    const geom::Segment& ccw_long = p.moves[6].path;
    expect_point(ccw_long.center, 5, -h);
    EXPECT_NEAR(ccw_long.sweep_rad, 5 * M_PI / 3, kEps);
    // Half circle: R = half the chord; CW from (0,0) to (10,0) goes over the top.
    const geom::Segment& half = p.moves[8].path;
    expect_point(half.center, 5, 0);
    EXPECT_NEAR(half.sweep_rad, -M_PI, kEps);
    expect_point(half.point_at(half.length_mm() / 2), 5, 5);
}

TEST(HostGcode, FullCircleWithIOnly) {
    const Program p = run_gcode("G0 X10 Y0\nG2 I-10 F100\n");
    ASSERT_EQ(p.moves.size(), 2u);
    const geom::Segment& c = p.moves[1].path;
    EXPECT_TRUE(c.is_arc);
    expect_point(c.center, 0, 0);
    EXPECT_NEAR(c.sweep_rad, -2 * M_PI, kEps);
    expect_point(c.end, 10, 0);
    EXPECT_NEAR(c.length_mm(), 20 * M_PI, 1e-9);
}

TEST(HostGcode, RelativeArcEndPoint) {
    const Program p = run_gcode("G0 X10 Y0\nG91 G3 X-10 Y10 I-10 F100\n");
    ASSERT_EQ(p.moves.size(), 2u);
    expect_point(p.moves[1].path.end, 0, 10);
    expect_point(p.moves[1].path.center, 0, 0);
}

TEST(HostGcode, ArcCentreIgnoresG92Offset) {
    const Program p = run_gcode("G0 X10 Y0\nG92 X0 Y0\nG3 X-10 Y10 I-10 F100\n");
    ASSERT_EQ(p.moves.size(), 2u);
    expect_point(p.moves[1].path.center, 0, 0);
    expect_point(p.moves[1].path.end, 0, 10);
}

TEST(HostGcode, ModalMotionRepeatsLastMotionWord) {
    const Program p = run_gcode("G1 X1 F100\nX2\nY3\nG0 X0\nY0\nG2 X2 Y0 I1\nX4 I1\n");
    ASSERT_EQ(p.moves.size(), 7u);
    EXPECT_EQ(p.moves[1].kind, MotionKind::Linear);
    expect_point(p.moves[1].path.end, 2, 0);
    EXPECT_EQ(p.moves[2].kind, MotionKind::Linear);
    expect_point(p.moves[2].path.end, 2, 3);
    EXPECT_EQ(p.moves[4].kind, MotionKind::Rapid);
    EXPECT_EQ(p.moves[6].kind, MotionKind::ArcCW);
    expect_point(p.moves[6].path.center, 3, 0);
}

TEST(HostGcode, MotionWordAloneOnlySetsTheMode) {
    const Program p = run_gcode("G1 F100\nX3\n");
    ASSERT_EQ(p.moves.size(), 1u);
    EXPECT_EQ(p.moves[0].kind, MotionKind::Linear);
}

TEST(HostGcode, CommentsAndBlockNumbers) {
    const Program p = run_gcode("(header comment)\nN10 G1 X1 (inline) Y2 F100 ; trailing\n; whole line\n\nN20X3\n");
    ASSERT_EQ(p.moves.size(), 2u);
    expect_point(p.moves[0].path.end, 1, 2);
    EXPECT_EQ(p.moves[0].line, 2);
    EXPECT_EQ(p.moves[1].line, 5);
    expect_point(p.moves[1].path.end, 3, 2);
}

TEST(HostGcode, NumberFormatsCaseAndSpaces) {
    const Program p = run_gcode("g01 x10. y-.5 f+100\nX +3.000 Y 1 0\nG1X-5Y-5\r\n");
    ASSERT_EQ(p.moves.size(), 3u);
    expect_point(p.moves[0].path.end, 10, -0.5);
    EXPECT_DOUBLE_EQ(p.moves[0].feed_mm_per_min, 100.0);
    expect_point(p.moves[1].path.end, 3, 10);
    expect_point(p.moves[2].path.end, -5, -5);
}

TEST(HostGcode, ZeroLengthMovesAreDropped) {
    const Program p = run_gcode("G1 X0 Y0 F100\nG0 X5\nG0 X5\nG91 G1 X0\n");
    ASSERT_EQ(p.moves.size(), 1u);
    EXPECT_EQ(p.moves[0].line, 2);
}

TEST(HostGcode, ProgramEndStopsReading) {
    const Program a = run_gcode("G1 X1 F100\nM30\nG41 not even G-code\n");
    ASSERT_EQ(a.moves.size(), 1u);
    const Program b = run_gcode("G1 X1 F100\nG1 X2 M2\nG1 X3\n");
    ASSERT_EQ(b.moves.size(), 2u);  // the motion on the M2 line still runs
    expect_point(b.moves[1].path.end, 2, 0);
}

TEST(HostGcode, LaserFollowsM3AndM5) {
    const Program p = run_gcode("G1 X1 F100\nM3 G1 X2\nG1 X3 S128\nM5\nG1 X4\n");
    ASSERT_EQ(p.moves.size(), 4u);
    EXPECT_FALSE(p.moves[0].laser_on);
    EXPECT_TRUE(p.moves[1].laser_on);
    EXPECT_TRUE(p.moves[2].laser_on);
    EXPECT_FALSE(p.moves[3].laser_on);
}

TEST(HostGcode, FeedUnitsAndRapidFeedOption) {
    InterpreterOptions opt;
    opt.feed_unit = FeedUnit::MmPerSecond;
    opt.rapid_feed_mm_per_min = 3000.0;
    const Program p = run_gcode("G1 X1 F10\nG0 X0\n", opt);
    ASSERT_EQ(p.moves.size(), 2u);
    EXPECT_DOUBLE_EQ(p.moves[0].feed_mm_per_min, 600.0);
    EXPECT_DOUBLE_EQ(p.moves[1].feed_mm_per_min, 3000.0);
}

TEST(HostGcode, FeedOnARapidLineIsKeptForLaterMoves) {
    const Program p = run_gcode("G0 X1 F500\nG1 X2\n");
    ASSERT_EQ(p.moves.size(), 2u);
    EXPECT_DOUBLE_EQ(p.moves[0].feed_mm_per_min, 1200.0);
    EXPECT_DOUBLE_EQ(p.moves[1].feed_mm_per_min, 500.0);
}

TEST(HostGcode, StartPositionOption) {
    InterpreterOptions opt;
    opt.start_mm = {5, 7};
    const Program p = run_gcode("G91 G0 X1\nG90 G0 X0 Y0\n", opt);
    ASSERT_EQ(p.moves.size(), 2u);
    expect_point(p.moves[0].path.start, 5, 7);
    expect_point(p.moves[0].path.end, 6, 7);
    expect_point(p.moves[1].path.end, 0, 0);
}

TEST(HostGcode, InterpretFileReadsFromDisk) {
    const std::string path = cnc::test::test_path("job.nc");
    {
        std::ofstream out(path);
        out << "G1 X3 Y4 F100\n";
    }
    const Program p = interpret_file(path, {});
    EXPECT_EQ(p.filename, path);
    ASSERT_EQ(p.moves.size(), 1u);
    EXPECT_DOUBLE_EQ(p.moves[0].path.length_mm(), 5.0);
}

}  // namespace
}  // namespace cnc::host
