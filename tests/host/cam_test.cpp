#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "host/core/cam.hpp"
#include "host_test_util.hpp"

namespace cnc::host {
namespace {

using test::expect_bad_input;
using test::run_gcode;

constexpr double kSpm = 160.0;  // seed 000 reference machine

std::vector<MotionSegment> cam_of(const std::string& gcode, const CamOptions& opt = {},
                                  const MachineModel& machine = {}) {
    return cam(run_gcode(gcode), machine, opt);
}

TEST(HostCam, WorkedExampleOfSection347) {
    const auto segs = cam_of("G1 X10.000 Y5.000 F1000\nG1 X10 Y0 F1000\n");
    ASSERT_EQ(segs.size(), 2u);
    EXPECT_EQ(segs[0].index, 1);
    EXPECT_EQ(segs[0].motion, MotionKind::Linear);
    EXPECT_EQ(segs[0].steps_x, 1600);
    EXPECT_EQ(segs[0].steps_y, 800);
    EXPECT_EQ(segs[0].feed, 894);
    EXPECT_DOUBLE_EQ(segs[0].path_feed_mm_per_min, 1000.0);
    EXPECT_EQ(segs[0].move, 0);
    EXPECT_EQ(segs[0].line, 1);
    EXPECT_DOUBLE_EQ(segs[0].dx_mm, 10.0);
    EXPECT_DOUBLE_EQ(segs[0].dy_mm, 5.0);
    EXPECT_EQ(segs[1].index, 2);
    EXPECT_EQ(segs[1].steps_x, 0);
    EXPECT_EQ(segs[1].steps_y, -800);
    EXPECT_EQ(segs[1].feed, 1000);
    EXPECT_EQ(segs[1].line, 2);
}

TEST(HostCam, AbsoluteRoundingHasNoDrift) {
    // 100 moves of 0.003 mm = 0.48 steps each: per-move rounding would give 0 steps; absolute rounding gives
    // exactly round(0.3 * 160) = 48 steps in total, one step at a time.
    std::ostringstream g;
    g << "G91 F100\n";
    for (int i = 0; i < 100; ++i) g << "G1 X0.003\n";
    const auto segs = cam_of(g.str());
    std::int64_t total = 0;
    for (const auto& s : segs) {
        EXPECT_EQ(s.steps_x, 1);
        EXPECT_EQ(s.steps_y, 0);
        total += s.steps_x;
    }
    EXPECT_EQ(segs.size(), 48u);
    EXPECT_EQ(total, std::llround(0.3 * kSpm));
    EXPECT_EQ(segs.back().index, 48);
}

TEST(HostCam, StartPositionIsRoundedAbsolutely) {
    InterpreterOptions iopt;
    iopt.start_mm = {0.004, 0.0};  // 0.64 steps -> the machine is at step 1
    const auto segs = cam(run_gcode("G1 X1 F100\n", iopt), {}, {});
    ASSERT_EQ(segs.size(), 1u);
    EXPECT_EQ(segs[0].steps_x, 159);
}

TEST(HostCam, ChordCountIsTheSmallestWithinTolerance) {
    const double r = 10.0;
    const double tol = 0.002;
    for (const double sweep : {M_PI / 2, M_PI, 2 * M_PI, 0.01}) {
        const std::int64_t n = chord_count(r, sweep, tol);
        EXPECT_LE(r * (1 - std::cos(sweep / n / 2)), tol) << sweep;
        if (n > 1) {
            EXPECT_GT(r * (1 - std::cos(sweep / (n - 1) / 2)), tol) << sweep;
        }
    }
    EXPECT_EQ(chord_count(r, M_PI / 2, tol), 40);
    EXPECT_EQ(chord_count(r, 2 * M_PI, tol), 158);
    EXPECT_EQ(chord_count(r, -2 * M_PI, tol), 158);
    EXPECT_EQ(chord_count(r, 0.01, tol), 1);
    // Tolerance >= radius: each chord spans at most half a turn.
    EXPECT_EQ(chord_count(0.001, 2 * M_PI, tol), 2);
}

// Step positions (in mm) reached after each segment, starting from `start_steps`.
std::vector<geom::Vec2> reached_mm(const std::vector<MotionSegment>& segs, std::int64_t x0, std::int64_t y0) {
    std::vector<geom::Vec2> pts;
    for (const auto& s : segs) {
        x0 += s.steps_x;
        y0 += s.steps_y;
        pts.push_back({static_cast<double>(x0) / kSpm, static_cast<double>(y0) / kSpm});
    }
    return pts;
}

TEST(HostCam, FullCircleChordEndsLieOnTheArc) {
    const Program prog = run_gcode("G0 X10 Y0\nG2 I-10 F600\n");
    const geom::Segment arc = prog.moves[1].path;
    const auto segs = cam(prog, {}, {});
    ASSERT_EQ(segs.size(), 1u + 158u);  // the rapid + every chord (each moves at least one step at R = 10)
    const auto pts = reached_mm(segs, 0, 0);
    const double half_step_diag = 0.5 * std::sqrt(2.0) / kSpm;
    for (std::size_t i = 1; i < segs.size(); ++i) {
        EXPECT_EQ(segs[i].motion, MotionKind::ArcCW);
        EXPECT_EQ(segs[i].move, 1);
        EXPECT_EQ(segs[i].line, 2);
        EXPECT_LE(std::fabs(geom::distance(pts[i], arc.center) - 10.0), half_step_diag + 1e-12) << i;
    }
    // Back at the start exactly.
    EXPECT_EQ(std::llround(pts.back().x_mm * kSpm), 1600);
    EXPECT_EQ(std::llround(pts.back().y_mm * kSpm), 0);
    // Between chord ends the arc stays within the chord tolerance plus the quantisation of the ends.
    for (std::size_t i = 1; i < pts.size(); ++i) {
        const geom::Segment chord = geom::Segment::line(pts[i - 1], pts[i]);
        const double a0 = std::atan2(pts[i - 1].y_mm, pts[i - 1].x_mm);
        const double a1 = std::atan2(pts[i].y_mm, pts[i].x_mm);
        const double mid = a0 + std::remainder(a1 - a0, 2 * M_PI) / 2;
        const geom::Vec2 on_arc{10.0 * std::cos(mid), 10.0 * std::sin(mid)};
        EXPECT_LE(chord.distance_to(on_arc), CamOptions{}.chord_tolerance_mm + half_step_diag) << i;
    }
}

TEST(HostCam, CcwArcKeepsMotionCodeThree) {
    const auto segs = cam_of("G0 X10\nG3 X0 Y10 I-10 F600\n");
    ASSERT_EQ(segs.size(), 1u + 40u);
    for (std::size_t i = 1; i < segs.size(); ++i) EXPECT_EQ(segs[i].motion, MotionKind::ArcCCW);
    std::int64_t x = 0, y = 0;
    for (const auto& s : segs) {
        x += s.steps_x;
        y += s.steps_y;
    }
    EXPECT_EQ(x, 0);
    EXPECT_EQ(y, 1600);
}

TEST(HostCam, CoarseToleranceGivesFewerChords) {
    CamOptions opt;
    opt.chord_tolerance_mm = 0.1;
    const auto segs = cam_of("G0 X10\nG3 X0 Y10 I-10 F600\n", opt);
    EXPECT_EQ(static_cast<std::int64_t>(segs.size()), 1 + chord_count(10.0, M_PI / 2, 0.1));
    EXPECT_EQ(chord_count(10.0, M_PI / 2, 0.1), 6);
}

TEST(HostCam, DominantAxisFeed) {
    const auto segs = cam_of("G1 X5 Y10 F1000\nG1 X15 Y0\nG1 X5 Y0\n");
    ASSERT_EQ(segs.size(), 3u);
    EXPECT_EQ(segs[0].feed, 894);   // Y dominant: 1000 * 10 / sqrt(125)
    EXPECT_EQ(segs[1].feed, 707);   // tie: X, 1000 / sqrt(2) = 707.1
    EXPECT_EQ(segs[2].feed, 1000);  // single axis: F unchanged
}

TEST(HostCam, FeedRoundingOption) {
    const std::string g = "G1 X10 Y10 F1001\n";  // 1001 / sqrt(2) = 707.81
    EXPECT_EQ(cam_of(g)[0].feed, 708);
    CamOptions trunc;
    trunc.feed_rounding = FeedRounding::Truncate;
    EXPECT_EQ(cam_of(g, trunc)[0].feed, 707);
}

TEST(HostCam, RapidFeedCorrectionOption) {
    const std::string g = "G0 X10 Y10\n";
    const auto corrected = cam_of(g);
    EXPECT_EQ(corrected[0].motion, MotionKind::Rapid);
    EXPECT_EQ(corrected[0].feed, 849);  // 1200 / sqrt(2) = 848.5
    EXPECT_DOUBLE_EQ(corrected[0].path_feed_mm_per_min, 1200.0);
    CamOptions raw;
    raw.correct_rapid_feed = false;
    EXPECT_EQ(cam_of(g, raw)[0].feed, 1200);
}

TEST(HostCam, FeedUsesStepQuantisedDisplacement) {
    // X 0.01 mm = 1.6 -> 2 steps, Y 0.003 mm = 0.48 -> 0 steps: the machine moves X only, so F is sent unchanged
    // (the unquantised direction would give 1000 * 0.01 / 0.01044 = 958).
    const auto segs = cam_of("G1 X0.01 Y0.003 F1000\n");
    ASSERT_EQ(segs.size(), 1u);
    EXPECT_EQ(segs[0].steps_x, 2);
    EXPECT_EQ(segs[0].steps_y, 0);
    EXPECT_EQ(segs[0].feed, 1000);
    EXPECT_DOUBLE_EQ(segs[0].dx_mm, 0.0125);
}

TEST(HostCam, DifferentStepsPerMmPerAxis) {
    MachineModel m;
    m.y.microsteps = 16;  // 80 steps/mm
    const auto segs = cam_of("G1 X10 Y10 F1000\nG1 X10 Y40\nG1 X20 Y60\n", {}, m);
    ASSERT_EQ(segs.size(), 3u);
    EXPECT_EQ(segs[0].steps_x, 1600);
    EXPECT_EQ(segs[0].steps_y, 800);
    EXPECT_EQ(segs[0].feed, 707);  // X has more steps; 10 mm of a 14.14 mm path
    EXPECT_EQ(segs[1].steps_y, 2400);
    EXPECT_DOUBLE_EQ(segs[1].dy_mm, 30.0);
    // 1600 steps on both axes: X is dominant on a tie (step_gen, seed 000 §5.4), though Y moves 20 mm to X's 10.
    EXPECT_EQ(segs[2].steps_x, 1600);
    EXPECT_EQ(segs[2].steps_y, 1600);
    EXPECT_EQ(segs[2].feed, 447);  // 1000 * 10 / sqrt(500)
}

TEST(HostCam, StepsOutsideInt32AreReported) {
    expect_bad_input([] { cam_of("G0 X0\nG1 X20000000 F1000\n"); },
                     {"t.nc:2:", "steps_x 3200000000 outside int32 (-2147483648..2147483647)"});
    expect_bad_input([] { cam_of("G0 Y-20000000\n"); }, {"t.nc:1:", "steps_y -3200000000 outside int32"});
}

TEST(HostCam, FeedOutsidePacketRangeIsReported) {
    expect_bad_input([] { cam_of("G1 X10 Y10 F0.5\n"); }, {"t.nc:1:", "rounds to 0", "1..65535"});
    expect_bad_input([] { cam_of("G1 X10 F70000\n"); }, {"t.nc:1:", "feed 70000", "1..65535"});
    InterpreterOptions fast;
    fast.rapid_feed_mm_per_min = 100000.0;
    expect_bad_input([&] { cam(run_gcode("G0 X1\n", fast), {}, {}); }, {"t.nc:1:", "feed 100000"});
}

TEST(HostCam, BadMachineOrToleranceIsReported) {
    MachineModel m;
    m.x.microsteps = 3;
    expect_bad_input([&] { cam_of("G0 X1\n", {}, m); }, {"machine x: microsteps 3"});
    CamOptions opt;
    opt.chord_tolerance_mm = 0.0;
    expect_bad_input([&] { cam_of("G0 X1\n", opt); }, {"chord_tolerance_mm must be > 0"});
    opt.chord_tolerance_mm = 1e-12;
    expect_bad_input([&] { cam_of("G0 X1000\nG2 I-1000 F100\n", opt); }, {"t.nc:2:", "chords"});
}

TEST(HostCam, EmptyProgramGivesNoSegments) { EXPECT_TRUE(cam_of("G21\n").empty()); }

TEST(HostNumerator, FromStepsPerMm) {
    EXPECT_EQ(numerator(160.0), 18'750'000u);
    EXPECT_EQ(numerator(80.0), 37'500'000u);
    EXPECT_EQ(numerator(160.0, 16'000'000), 6'000'000u);
    EXPECT_EQ(numerator(3.0), 1'000'000'000u);
    expect_bad_input([] { numerator(0.0); }, {"steps_per_mm must be > 0"});
    expect_bad_input([] { numerator(0.5); }, {"NUMERATOR", "6000000000", "uint32"});
    expect_bad_input([] { numerator(1e10); }, {"NUMERATOR", "uint32"});
}

}  // namespace
}  // namespace cnc::host
