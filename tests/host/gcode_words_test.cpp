// The RS274/NGC, grbl and laser words beyond the seed's set: their effect on the XY moves, the host waits and
// the ignored-word list, each against a position or time worked out by hand from the G-code.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "common/math_constants.hpp"
#include "host_test_util.hpp"

namespace cnc::host {
namespace {

using test::expect_point;
using test::run_gcode;

TEST(HostGcodeWords, DwellIsAWaitBeforeTheNextMoveInSeconds) {
    const Program p = run_gcode("G1 X10 F600\nG4 P2.5\nG4 S1\nG1 Y10\nG4 P0.5\nM2\n");
    ASSERT_EQ(p.waits.size(), 3u);
    EXPECT_EQ(p.waits[0].before_move, 1u);
    EXPECT_DOUBLE_EQ(p.waits[0].seconds, 2.5);
    EXPECT_EQ(p.waits[0].line, 2);
    EXPECT_DOUBLE_EQ(p.waits[1].seconds, 1.0);  // Marlin's S form, in seconds
    EXPECT_EQ(p.waits[2].before_move, 2u);      // after the last move
    EXPECT_DOUBLE_EQ(p.wait_s(WaitCause::Dwell), 4.0);
    EXPECT_DOUBLE_EQ(p.wait_s_between(0, 2), 3.5);
    EXPECT_FALSE(p.moves[1].power_s);  // G4's S is the dwell, not the laser power
}

TEST(HostGcodeWords, OperatorPausesTakeTheConfiguredTime) {
    InterpreterOptions opt;
    opt.operator_pause_s = 7.0;
    const Program p = run_gcode("M0\nG0 X1\nM1\nM60\n", opt);
    EXPECT_DOUBLE_EQ(p.wait_s(WaitCause::OperatorPause), 21.0);
}

TEST(HostGcodeWords, ZOnlyMoveIsTimedAtItsFeedAndAMixedMoveSharesF) {
    const Program p = run_gcode("G1 Z5 F300\nG0 Z0\nG1 X30 Z-40 F600\n");
    // 5 mm at 300 mm/min = 1 s; the rapid 5 mm at 1200 mm/min = 0.25 s.
    ASSERT_EQ(p.waits.size(), 2u);
    EXPECT_DOUBLE_EQ(p.waits[0].seconds, 1.0);
    EXPECT_DOUBLE_EQ(p.waits[1].seconds, 0.25);
    EXPECT_EQ(p.waits[0].cause, WaitCause::OtherAxes);
    // X30 Z-40: 50 mm at F600 = 5 s, so the XY path runs 30 mm in 5 s = 360 mm/min.
    ASSERT_EQ(p.moves.size(), 1u);
    EXPECT_NEAR(p.moves[0].feed_mm_per_min, 360.0, 1e-9);
    EXPECT_DOUBLE_EQ(p.moves[0].z_end_mm, -40.0);
    EXPECT_DOUBLE_EQ(p.z_travel_mm, 50.0);
}

TEST(HostGcodeWords, ZMovesStayWithinTheZVelocityLimit) {
    InterpreterOptions opt;
    opt.z_max_feed_mm_per_min = 60.0;  // machine.z.max_velocity_mm_per_s = 1
    const Program p = run_gcode("G1 Z5 F300\nG1 X30 Z-35 F600\n", opt);
    // 5 mm at 1 mm/s = 5 s instead of 1 s at F300.
    ASSERT_EQ(p.waits.size(), 1u);
    EXPECT_DOUBLE_EQ(p.waits[0].seconds, 5.0);
    // X30 Z-40 (50 mm): Z's 40 mm at 1 mm/s take 40 s, so the XY path runs 30 mm in 40 s = 45 mm/min.
    EXPECT_NEAR(p.moves[0].feed_mm_per_min, 45.0, 1e-9);
}

TEST(HostGcodeWords, WorkOffsetsG10AndCoordinateSystems) {
    const Program p = run_gcode(
        "G10 L2 P1 X10 Y20\nG0 X1 Y1\nG55 X1 Y1\nG10 L2 P2 X100\nG0 X0\nG10 L20 P0 X5\nG0 X5 Y0\nG54 G0 X0 Y0\n");
    expect_point(p.moves[0].path.end, 11, 21);  // G54 origin at (10, 20)
    expect_point(p.moves[1].path.end, 1, 1);    // G55 still at machine 0
    expect_point(p.moves[2].path.end, 100, 1);  // G55 origin moved to X100
    // L20 P0: the tool (machine X100) is X5 in G55, so G55's X origin is 95; X5 Y0 = machine (100, 0).
    expect_point(p.moves[3].path.end, 100, 0);
    expect_point(p.moves[4].path.end, 10, 20);
}

TEST(HostGcodeWords, WorkOffsetsG10InInches) {
    // G10's coordinates are in the program's units (RS274/NGC): under G20, 1 inch is machine 25.4 mm.
    const Program p = run_gcode("G20\nG10 L2 P1 X1 Y2\nG0 X1 Y1\nG10 L20 P1 X0.5\nG0 X1 Y0\n");
    expect_point(p.moves[0].path.end, 2 * 25.4, 3 * 25.4);  // G54 origin at (25.4, 50.8)
    // L20: the tool (machine X 50.8) is X0.5 in, so G54's X origin is 50.8 - 12.7 = 38.1; X1 = machine 63.5.
    expect_point(p.moves[1].path.end, 38.1 + 25.4, 2 * 25.4);
}

TEST(HostGcodeWords, G53AndG28GoToMachineCoordinates) {
    const Program p =
        run_gcode("G10 L2 P1 X50 Y50\nG0 X10 Y10\nG53 G0 X5 Y5\nG28\nG0 X1\nG28 X3\nG28.1\nG0 X20\nG28\n");
    expect_point(p.moves[0].path.end, 60, 60);
    expect_point(p.moves[1].path.end, 5, 5);   // G53: machine coordinates
    expect_point(p.moves[2].path.end, 0, 0);   // G28 with no axes: home, machine 0
    expect_point(p.moves[3].path.end, 51, 0);  // X1 in G54
    expect_point(p.moves[4].path.end, 53, 0);  // G28 X3: through program X3 ...
    expect_point(p.moves[5].path.end, 0, 0);   // ... then X alone to home
    expect_point(p.moves[7].path.end, 0, 0);   // G28.1 stored machine (0, 0)
}

TEST(HostGcodeWords, G92FamilySetsResetsAndRestoresTheOffset) {
    const Program p = run_gcode("G0 X10\nG92 X0\nG0 X5\nG92.2\nG0 X5\nG92.3\nG0 X1\nG92.1\nG0 X2\n");
    expect_point(p.moves[1].path.end, 15, 0);  // G92 X0 at machine 10
    expect_point(p.moves[2].path.end, 5, 0);   // G92.2: offsets off
    expect_point(p.moves[3].path.end, 11, 0);  // G92.3: restored
    expect_point(p.moves[4].path.end, 2, 0);   // G92.1: reset
}

TEST(HostGcodeWords, AbsoluteArcCentresWithG90_1) {
    const Program p = run_gcode("G10 L2 P1 X5\nG0 X15 Y0\nG90.1 G3 X5 Y10 I5 J0 F100\nG91.1 G3 X-5 Y0 I0 J-10\n");
    ASSERT_EQ(p.moves.size(), 3u);
    expect_point(p.moves[1].path.center, 10, 0);  // I5 J0 in G54 = machine (10, 0)
    expect_point(p.moves[2].path.center, 10, 0);  // relative: (10, 10) + (0, -10)
    EXPECT_NEAR(p.moves[1].path.sweep_rad, M_PI / 2, 1e-12);
}

TEST(HostGcodeWords, InverseTimeFeedGivesTheMoveItsTime) {
    // G93 F2: the move takes 1/2 min; 10 mm in 0.5 min = 20 mm/min.
    const Program p = run_gcode("G93 G1 X10 F2\nG94 G1 X20 F600\n");
    EXPECT_NEAR(p.moves[0].feed_mm_per_min, 20.0, 1e-9);
    EXPECT_DOUBLE_EQ(p.moves[1].feed_mm_per_min, 600.0);
    test::expect_gcode_error("G93 G1 X10 F2\nG1 X20\n", {"t.nc:2:", "inverse-time", "F"});
}

TEST(HostGcodeWords, FeedOptionReplacesEveryFeedWordButNotInverseTime) {
    // scenario.feed_mm_per_min = 1500: F800 in mm, F10 in inches (254 mm/min) and F5 in mm/s all read as 1500 mm/min;
    // the rapids keep the rapid feed, and G93's F2 still gives its move 1/2 min (10 mm: 20 mm/min).
    InterpreterOptions opt;
    opt.feed_mm_per_min = 1500.0;
    const Program p = run_gcode("G1 X10 F800\nG20 G1 X1 F10\nG21 G0 X0\nG93 G1 X10 F2\n", opt);
    ASSERT_EQ(p.moves.size(), 4u);
    EXPECT_DOUBLE_EQ(p.moves[0].feed_mm_per_min, 1500.0);
    EXPECT_DOUBLE_EQ(p.moves[1].feed_mm_per_min, 1500.0);
    EXPECT_DOUBLE_EQ(p.moves[2].feed_mm_per_min, opt.rapid_feed_mm_per_min);
    EXPECT_NEAR(p.moves[3].feed_mm_per_min, 20.0, 1e-9);
    opt.feed_unit = FeedUnit::MmPerSecond;
    EXPECT_DOUBLE_EQ(run_gcode("G1 X10 F5\n", opt).moves[0].feed_mm_per_min, 1500.0);
    test::expect_bad_input([&] { run_gcode("G1 X10 F0\n", opt); }, {"t.nc:1:", "feed must be > 0"});  // still checked
}

TEST(HostGcodeWords, PathControlAndLaserStateTravelWithTheMove) {
    const Program p = run_gcode("G64 P0.02\nM4 S300\nG1 X1 F100\nG61\nM3 S0\nG1 X2\nG61.1 M5\nG1 X3\n");
    ASSERT_TRUE(p.moves[0].path_control);
    EXPECT_EQ(p.moves[0].path_control->mode, PathMode::Blend);
    EXPECT_DOUBLE_EQ(*p.moves[0].path_control->tolerance_mm, 0.02);
    EXPECT_EQ(p.moves[0].laser_mode, LaserMode::Dynamic);
    EXPECT_TRUE(p.moves[0].laser_intended());
    // LinuxCNC's G-code reference: G61 exact path, G61.1 exact stop.
    EXPECT_EQ(p.moves[1].path_control->mode, PathMode::ExactPath);
    EXPECT_FALSE(p.moves[1].laser_intended());  // S0
    EXPECT_EQ(p.moves[2].path_control->mode, PathMode::ExactStop);
    EXPECT_FALSE(p.moves[2].laser_intended());  // M5
}

TEST(HostGcodeWords, IgnoredWordsAreListedOnceWithEveryLine) {
    const Program p = run_gcode("%\nO1000\nT1 M6\nG40 G49 G80\n/G0 X50\nM8\nG0 X1\nT1\nM106 S255\nM9\n%\nG0 X99\n");
    ASSERT_EQ(p.moves.size(), 1u);  // the block-delete line and everything after the closing % are skipped
    std::vector<std::pair<std::string, std::size_t>> got;
    for (const IgnoredWord& w : p.ignored) got.emplace_back(w.word, w.lines.size());
    const std::vector<std::pair<std::string, std::size_t>> want{{"%", 2},   {"O1000", 1}, {"T1", 2},  {"M6", 1},
                                                                {"G40", 1}, {"G49", 1},   {"G80", 1}, {"/", 1},
                                                                {"M8", 1},  {"M106", 1},  {"M9", 1}};
    EXPECT_EQ(got, want);
    EXPECT_EQ(p.ignored[2].lines, (std::vector<int>{3, 8}));
}

// A file without LF ends its lines in CR (classic Mac); in a file with LF, a CR outside CR* LF is blank space.
TEST(HostGcodeWords, LineEndingsAndByteOrderMark) {
    const Program cr = run_gcode("\xEF\xBB\xBFG21\rG0 X1\rM5\rG0 X2\rG0 X3\r");
    ASSERT_EQ(cr.moves.size(), 3u);
    EXPECT_EQ(cr.moves[2].line, 5);
    EXPECT_EQ(cr.lines, 5);
    const Program lf = run_gcode("G0 X1\rY2\r\r\nG0 X3\r\nG0 Y4\n");
    ASSERT_EQ(lf.moves.size(), 3u);
    expect_point(lf.moves[0].path.end, 1, 2);
    EXPECT_EQ(lf.moves[1].line, 2);
    EXPECT_EQ(lf.moves[2].line, 3);
}

// RS274/NGC lets a user M code (M100-M199) take P and Q; Marlin's fan code M106 takes P (the fan) and S.
TEST(HostGcodeWords, PAndQBesideAnIgnoredCodeAreIgnoredWithIt) {
    const Program p = run_gcode("M100 P100\nG0 X3 M106 P0 S255\nM101 Q2\nM107\n");
    ASSERT_EQ(p.moves.size(), 1u);
    std::vector<std::pair<std::string, std::vector<int>>> got;
    for (const IgnoredWord& w : p.ignored) got.emplace_back(w.word, w.lines);
    const std::vector<std::pair<std::string, std::vector<int>>> want{{"M100", {1}}, {"P", {1, 2}}, {"M106", {2}},
                                                                     {"M101", {3}}, {"Q", {3}},    {"M107", {4}}};
    EXPECT_EQ(got, want);
    // With nothing on the line to use them, they are errors, as in LinuxCNC.
    test::expect_gcode_error("G1 X1 F100 P3\n", {"t.nc:1:", "P is used only with G2/G3 (turns), G4, G10, G64"});
    test::expect_gcode_error("G0 X3 Q7\n", {"t.nc:1:", "Q is used only with G64"});
    InterpreterOptions strict;
    strict.policy = GcodePolicy::Strict;
    test::expect_bad_input([&] { run_gcode("M100 P100\n", strict); }, {"'M100'", "'P'"});
}

// LinuxCNC: "P value should be 1 or greater with G2 or G3", "P value not an integer".
TEST(HostGcodeWords, ArcTurnsAreAWholeNumberFromOne) {
    test::expect_gcode_error("G0 X10\nG3 X10 Y0 I-10 P0 F600\n", {"t.nc:2:", "G3 P (turns) must be 1 .. 1000"});
    test::expect_gcode_error("G0 X10\nG2 X10 Y0 I-10 P1.5 F600\n", {"t.nc:2:", "G2 P (turns) must be a whole number"});
    const Program modal = run_gcode("G0 X10\nG3 X10 Y0 I-10 F600\nX10 Y0 I-10 P3\n");
    ASSERT_EQ(modal.moves.size(), 3u);
    EXPECT_NEAR(modal.moves[2].path.sweep_rad, 3.0 * kTwoPi, 1e-12);
}

TEST(HostGcodeWords, ArcsOutsideTheXyPlaneAreRefused) {
    test::expect_gcode_error("G18\nG2 X1 Z1 I1 F100\n", {"t.nc:2:", "G18 (XZ)", "XY plane"});
}

}  // namespace
}  // namespace cnc::host
