#include <gtest/gtest.h>

#include <algorithm>
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

// Step positions reached after each segment, starting from (x0, y0) steps, in mm (per-axis steps/mm).
std::vector<geom::Vec2> reached_mm(const std::vector<MotionSegment>& segs, std::int64_t x0, std::int64_t y0,
                                   double spm_x = kSpm, double spm_y = kSpm) {
    std::vector<geom::Vec2> pts;
    for (const auto& s : segs) {
        x0 += s.steps_x;
        y0 += s.steps_y;
        pts.push_back({static_cast<double>(x0) / spm_x, static_cast<double>(y0) / spm_y});
    }
    return pts;
}

// Largest distance between the arc (radius r about c, from a's angle to b's angle the short way) and chord a-b:
// the chord's contour error measured from its actual grid end points.
double chord_error_mm(geom::Vec2 a, geom::Vec2 b, geom::Vec2 c, double r) {
    const double t0 = std::atan2(a.y_mm - c.y_mm, a.x_mm - c.x_mm);
    const double dt = std::remainder(std::atan2(b.y_mm - c.y_mm, b.x_mm - c.x_mm) - t0, 2 * M_PI);
    const geom::Segment chord = geom::Segment::line(a, b);
    double worst = 0.0;
    constexpr int kSamples = 200;  // at most R (span/200)^2 / 8 below the true maximum: < 1e-7 mm here
    for (int i = 0; i <= kSamples; ++i) {
        const double t = t0 + dt * i / kSamples;
        worst = std::max(worst, chord.distance_to(c + geom::Vec2{r * std::cos(t), r * std::sin(t)}));
    }
    return worst;
}

double residual_mm(geom::Vec2 p, geom::Vec2 c, double r) {
    return std::fabs(geom::distance(p, c) - r);
}

struct ArcChording {
    double max_residual_mm = 0;  // interior chord ends only
    double max_chord_error_mm = 0;
    double max_span_rad = 0;
    double travelled_rad = 0;  // signed, summed over the chords
};

// Checks the chords of one arc (ends[0] = the start, then every chord end) and measures them: every chord
// advances strictly in the arc's direction and no further than `max_span_rad`, and its contour error is at
// most the tolerance plus the residuals of its two ends.
ArcChording check_chords(const std::vector<geom::Vec2>& ends, geom::Vec2 c, double r, bool ccw, double tol,
                         double max_span_rad) {
    ArcChording m;
    for (std::size_t i = 1; i < ends.size(); ++i) {
        const double a0 = std::atan2(ends[i - 1].y_mm - c.y_mm, ends[i - 1].x_mm - c.x_mm);
        const double a1 = std::atan2(ends[i].y_mm - c.y_mm, ends[i].x_mm - c.x_mm);
        const double step = std::remainder(a1 - a0, 2 * M_PI);
        EXPECT_GT(ccw ? step : -step, 0.0) << "chord " << i << " goes backwards or is empty";
        EXPECT_LE(std::fabs(step), max_span_rad) << i;
        m.max_span_rad = std::max(m.max_span_rad, std::fabs(step));
        m.travelled_rad += step;
        const double err = chord_error_mm(ends[i - 1], ends[i], c, r);
        EXPECT_LE(err, tol + residual_mm(ends[i - 1], c, r) + residual_mm(ends[i], c, r) + 1e-12) << i;
        m.max_chord_error_mm = std::max(m.max_chord_error_mm, err);
        if (i + 1 < ends.size()) m.max_residual_mm = std::max(m.max_residual_mm, residual_mm(ends[i], c, r));
    }
    return m;
}

// The chord ends of arc move 1 (after a G0 to its start) as positions in mm, ends[0] = the start.
std::vector<geom::Vec2> arc_ends(const std::vector<MotionSegment>& segs, double spm_x = kSpm, double spm_y = kSpm) {
    const auto pts = reached_mm(segs, 0, 0, spm_x, spm_y);
    std::vector<geom::Vec2> ends{pts.front()};
    for (std::size_t i = 1; i < segs.size(); ++i) {
        EXPECT_EQ(segs[i].move, 1);
        EXPECT_TRUE(segs[i].steps_x != 0 || segs[i].steps_y != 0) << "empty chord " << i;
        ends.push_back(pts[i]);
    }
    return ends;
}

double max_chord_rad(double r, double tol) {
    return 4.0 * std::asin(std::sqrt(tol / (2.0 * r)));
}

CamOptions round_ends() {
    CamOptions opt;
    opt.chord_ends = ChordEnds::Round;
    return opt;
}

// ChordEnds::OnArc's rule as cam.cpp describes it, written out here without its code: interior end k is the grid
// point nearest the circle within +-W steps per axis of the rounded ideal end k (the corners of its grid cell when
// W = 0), W = floor(min(3, 0.05 x longest chord x steps/mm)) with the chords counted for 0.8 of the tolerance.
// (The rule also keeps the ends in order; at the radii checked with it the windows, a few steps wide, never reach
// a neighbouring end some 50 steps away.)
int window_steps_of(double r, double tol, double spm) {
    return static_cast<int>(std::min(3.0, std::floor(0.05 * max_chord_rad(r, kOnArcSagittaShare * tol) * r * spm)));
}

double nearest_in_window_mm(geom::Vec2 ideal, geom::Vec2 c, double r, double spm_x, double spm_y, int w_x, int w_y) {
    const auto range = [](double mm, double spm, int w) {
        const double steps = mm * spm;
        return w > 0 ? std::pair<std::int64_t, std::int64_t>{std::llround(steps) - w, std::llround(steps) + w}
                     : std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(std::floor(steps)),
                                                             static_cast<std::int64_t>(std::ceil(steps))};
    };
    const auto [x0, x1] = range(ideal.x_mm, spm_x, w_x);
    const auto [y0, y1] = range(ideal.y_mm, spm_y, w_y);
    double best = INFINITY;
    for (std::int64_t x = x0; x <= x1; ++x) {
        for (std::int64_t y = y0; y <= y1; ++y) {
            best = std::min(best, residual_mm({static_cast<double>(x) / spm_x, static_cast<double>(y) / spm_y}, c, r));
        }
    }
    return best;
}

// Every interior end of a full-turn arc (ends[0] = the start; none left out) is as near the circle as the nearest
// point of its window (a tie may pick either point); returns the largest of those nearest distances: the residual
// the rule promises, computed without the CAM.
double expect_ends_nearest_in_window(const std::vector<geom::Vec2>& ends, geom::Vec2 c, double r, double a0_rad,
                                     double sweep_rad, double tol, double spm_x, double spm_y) {
    const std::size_t n = ends.size() - 1;
    const int w_x = window_steps_of(r, tol, spm_x);
    const int w_y = window_steps_of(r, tol, spm_y);
    double worst = 0.0;
    for (std::size_t k = 1; k < n; ++k) {
        const double a = a0_rad + sweep_rad * static_cast<double>(k) / static_cast<double>(n);
        const double best =
            nearest_in_window_mm(c + geom::Vec2{r * std::cos(a), r * std::sin(a)}, c, r, spm_x, spm_y, w_x, w_y);
        EXPECT_NEAR(residual_mm(ends[k], c, r), best, 1e-12) << "end " << k;
        worst = std::max(worst, best);
    }
    return worst;
}

// Bounds that follow from the rule, for windows of W >= 1 (h = the step on the axis, n = the circle's normal):
// - Round's end is within half a step per axis of the ideal end, which is on the circle, so within
//   0.5 sqrt(hx^2 + hy^2) of it (triangle inequality): 0.71 step when hx = hy. OnArc's end is never further off
//   than that rounded end (the rule falls back on it).
// - Along the axis i that the circle crosses more steeply (|n_i| >= 1/sqrt(2)), the window's points from the rounded
//   end reach W h_i |n_i| across the circle on either side, at least the rounded end's 0.71 step when W h_i |n_i|
//   >= 0.5 sqrt(hx^2 + hy^2) (true for every window below), so two neighbours straddle the circle; their distances
//   to the centre differ by at most h_i, so the nearer is within h_i / 2 of it: OnArc's residual <= max(hx, hy) / 2.
// - A chord's sagitta is at most the tolerance when its span is at most max_chord_rad (check_chords checks the
//   spans), so its contour error is at most the tolerance plus its two ends' residuals.
// - The spans add up to the sweep, so the longest is at least the sweep / n.
double round_bound_mm(double spm_x, double spm_y) {
    return 0.5 * std::hypot(1.0 / spm_x, 1.0 / spm_y);
}
double on_arc_bound_mm(double spm_x, double spm_y) {
    return 0.5 * std::max(1.0 / spm_x, 1.0 / spm_y);
}

TEST(HostCam, RoundChordEndsAreWithinHalfAStepOfTheArc) {
    const Program prog = run_gcode("G0 X10 Y0\nG2 I-10 F600\n");
    const geom::Segment arc = prog.moves[1].path;
    const auto segs = cam(prog, {}, round_ends());
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
        const double err = chord_error_mm(pts[i - 1], pts[i], arc.center, 10.0);
        EXPECT_LE(err, CamOptions{}.chord_tolerance_mm + half_step_diag) << i;
    }
}

TEST(HostCam, RoundIsPerAxisRoundingOfTheIdealChordEnds) {
    // Off-grid centre and radius, different steps/mm per axis, a partial CCW arc: every chord end is llround of
    // the inscribed polygon's vertex per axis (seed 000 §3.4.4), as before ChordEnds existed.
    MachineModel m;
    m.y.microsteps = 16;  // 80 steps/mm
    const double spm_y = 80.0;
    const Program prog = run_gcode("G0 X3.0031 Y-1.2347\nG3 X-3.3484 Y3.1443 I-3.0002 J2.4441 F600\n");
    const geom::Segment arc = prog.moves[1].path;
    const auto segs = cam(prog, m, round_ends());
    const std::int64_t n = chord_count(arc.radius_mm(), arc.sweep_rad, 0.002);
    ASSERT_EQ(segs.size(), 1u + static_cast<std::size_t>(n));
    const double a0 = std::atan2(arc.start.y_mm - arc.center.y_mm, arc.start.x_mm - arc.center.x_mm);
    std::int64_t x = 0, y = 0;
    for (std::int64_t k = 1; k <= n; ++k) {
        const double a = a0 + arc.sweep_rad * static_cast<double>(k) / static_cast<double>(n);
        const double r = arc.radius_mm();
        const geom::Vec2 p = k < n ? arc.center + geom::Vec2{std::cos(a) * r, std::sin(a) * r} : arc.end;
        x += segs[static_cast<std::size_t>(k)].steps_x;
        y += segs[static_cast<std::size_t>(k)].steps_y;
        EXPECT_EQ(segs[0].steps_x + x, std::llround(p.x_mm * kSpm)) << k;
        EXPECT_EQ(segs[0].steps_y + y, std::llround(p.y_mm * spm_y)) << k;
    }
}

TEST(HostCam, OnArcFullCircleR10) {
    // seed 000 reference machine, grbl's tolerance: the case whose contour error motivated ChordEnds::OnArc.
    const double tol = CamOptions{}.chord_tolerance_mm;
    const Program prog = run_gcode("G0 X10 Y0\nG2 I-10 F600\n");
    const auto segs = cam(prog, {}, {});
    // Counted for 0.8 x tol: 176 chords (158 at tol), none dropped as empty.
    EXPECT_EQ(chord_count(10.0, 2 * M_PI, kOnArcSagittaShare * tol), 176);
    ASSERT_EQ(segs.size(), 1u + 176u);
    for (std::size_t i = 1; i < segs.size(); ++i) EXPECT_EQ(segs[i].motion, MotionKind::ArcCW);
    const auto ends = arc_ends(segs);
    const ArcChording m = check_chords(ends, {0, 0}, 10.0, false, tol, max_chord_rad(10.0, tol));
    // W = floor(0.05 x 0.358 mm x 160) = 2. Every end is its window's nearest point to the circle; the largest of
    // those is 0.183 step (1.14 um), within OnArc's half step, where Round's bound is 0.71 step.
    const double promised = expect_ends_nearest_in_window(ends, {0, 0}, 10.0, 0.0, -2 * M_PI, tol, kSpm, kSpm);
    EXPECT_DOUBLE_EQ(m.max_residual_mm, promised);
    EXPECT_LE(m.max_residual_mm, on_arc_bound_mm(kSpm, kSpm));
    // The longest span is between the mean, 2 pi / 176 = 0.8925 of the tolerance's span, and that span.
    EXPECT_GE(m.max_span_rad, 2 * M_PI / 176);
    EXPECT_LE(m.max_span_rad, max_chord_rad(10.0, tol));
    EXPECT_LE(m.max_chord_error_mm, tol + 2 * m.max_residual_mm);
    EXPECT_NEAR(m.travelled_rad, -2 * M_PI, 1e-12);
    // The last end is the rounded programmed end: the start again.
    EXPECT_DOUBLE_EQ(ends.back().x_mm, 10.0);
    EXPECT_DOUBLE_EQ(ends.back().y_mm, 0.0);
}

TEST(HostCam, OnArcBeatsRoundOnAnOffGridCircle) {
    // Centre off the grid. Where the tangent runs along an axis, the grid points within a few steps
    // along the arc are all about as far from the circle as the rounded one, so the largest residual is close
    // to half a step there; it is still below Round's, and so is the largest chord error.
    const double tol = CamOptions{}.chord_tolerance_mm;
    const geom::Vec2 c{0.0031, 0.0007};
    const std::string g = "G0 X10.0031 Y0.0007\nG3 I-10 J0 F600\n";
    const auto on_arc = check_chords(arc_ends(cam_of(g)), c, 10.0, true, tol, max_chord_rad(10.0, tol));
    // Round's count is for the full tolerance, so its rounded ends make some chords a little longer.
    const auto round =
        check_chords(arc_ends(cam_of(g, round_ends())), c, 10.0, true, tol, 1.05 * max_chord_rad(10.0, tol));
    // OnArc: every end its window's nearest (0.496 step at worst, near the axes), within its half step; Round
    // within its 0.71 step; OnArc nearer on both counts.
    const double promised = expect_ends_nearest_in_window(arc_ends(cam_of(g)), c, 10.0, 0.0, 2 * M_PI, tol, kSpm, kSpm);
    EXPECT_DOUBLE_EQ(on_arc.max_residual_mm, promised);
    EXPECT_LE(on_arc.max_residual_mm, on_arc_bound_mm(kSpm, kSpm));
    EXPECT_LE(round.max_residual_mm, round_bound_mm(kSpm, kSpm));
    EXPECT_LT(on_arc.max_residual_mm, round.max_residual_mm);
    EXPECT_LT(on_arc.max_chord_error_mm, round.max_chord_error_mm);
    EXPECT_LE(on_arc.max_chord_error_mm, tol + 2 * on_arc.max_residual_mm);
    EXPECT_GE(on_arc.max_span_rad, 2 * M_PI / 176);
    EXPECT_NEAR(on_arc.travelled_rad, 2 * M_PI, 1e-12);
}

TEST(HostCam, OnArcWithDifferentStepsPerMmPerAxis) {
    MachineModel mm;
    mm.y.microsteps = 16;  // 80 steps/mm: a Y step is 12.5 um, and residuals are compared in mm
    const double tol = CamOptions{}.chord_tolerance_mm;
    const std::string g = "G0 X10 Y0\nG2 I-10 F600\n";
    const auto segs = cam_of(g, {}, mm);
    ASSERT_EQ(segs.size(), 1u + 176u);
    const auto ends = arc_ends(segs, kSpm, 80.0);
    const auto m = check_chords(ends, {0, 0}, 10.0, false, tol, max_chord_rad(10.0, tol));
    const auto r = check_chords(arc_ends(cam_of(g, round_ends(), mm), kSpm, 80.0), {0, 0}, 10.0, false, tol,
                                1.05 * max_chord_rad(10.0, tol));
    // W = 2 on X, floor(0.05 x 0.358 mm x 80) = 1 on Y. Near +-Y the residual is along Y, where half a step is
    // 6.25 um: every end its window's nearest (5.695 um at worst), within that; Round within
    // 0.5 sqrt(6.25^2 + 12.5^2) = 6.99 um.
    const double promised = expect_ends_nearest_in_window(ends, {0, 0}, 10.0, 0.0, -2 * M_PI, tol, kSpm, 80.0);
    EXPECT_DOUBLE_EQ(m.max_residual_mm, promised);
    EXPECT_LE(m.max_residual_mm, on_arc_bound_mm(kSpm, 80.0));
    EXPECT_LE(r.max_residual_mm, round_bound_mm(kSpm, 80.0));
    EXPECT_LE(m.max_chord_error_mm, tol + 2 * m.max_residual_mm);
    EXPECT_LE(r.max_chord_error_mm, tol + 2 * r.max_residual_mm);
    EXPECT_GE(m.max_span_rad, 2 * M_PI / 176);
    EXPECT_NEAR(m.travelled_rad, -2 * M_PI, 1e-12);
    EXPECT_DOUBLE_EQ(ends.back().x_mm, 10.0);
    EXPECT_DOUBLE_EQ(ends.back().y_mm, 0.0);
}

TEST(HostCam, OnArcTinyRadiusSearchesTheFourCorners) {
    // R = 0.05 mm = 8 steps: W = floor(0.05 x 0.507 rad x 8 steps) = 0, so each interior end is a corner of the
    // grid cell holding its ideal end (13 chords for 0.8 x tol).
    const double tol = CamOptions{}.chord_tolerance_mm;
    const auto segs = cam_of("G0 X0.05 Y0\nG3 I-0.05 F600\n");
    const std::int64_t n = chord_count(0.05, 2 * M_PI, kOnArcSagittaShare * tol);
    EXPECT_EQ(n, 13);
    ASSERT_EQ(segs.size(), 1u + 13u);
    const auto ends = arc_ends(segs);
    for (std::int64_t k = 1; k < n; ++k) {
        const double a = 2 * M_PI * static_cast<double>(k) / static_cast<double>(n);
        const geom::Vec2 e = ends[static_cast<std::size_t>(k)];
        EXPECT_LT(std::fabs(e.x_mm - 0.05 * std::cos(a)) * kSpm, 1.0) << k;
        EXPECT_LT(std::fabs(e.y_mm - 0.05 * std::sin(a)) * kSpm, 1.0) << k;
    }
    // On so coarse a grid an end may sit at any corner of its ideal end's cell, up to a cell diagonal (sqrt(2)
    // steps, 0.177 rad at R = 8 steps) from it along the arc: a span is at most 2 pi / 13 + 2 x 0.177 rad, 1.47 x
    // the tolerance's span (1.11 x here). The residual keeps Round's bound (the rule falls back on the rounded end).
    const double longest_rad = 2 * M_PI / 13 + 2 * std::sqrt(2.0) / (0.05 * kSpm);
    const auto m = check_chords(ends, {0, 0}, 0.05, true, tol, longest_rad);
    EXPECT_GE(m.max_span_rad, 2 * M_PI / 13);
    EXPECT_LE(m.max_residual_mm, round_bound_mm(kSpm, kSpm));
    EXPECT_LE(m.max_chord_error_mm, tol + 2 * m.max_residual_mm);
    EXPECT_NEAR(m.travelled_rad, 2 * M_PI, 1e-12);
    EXPECT_DOUBLE_EQ(ends.back().x_mm, 0.05);
    EXPECT_DOUBLE_EQ(ends.back().y_mm, 0.0);
}

TEST(HostCam, OnArcChordsShorterThanAStepAreLeftOut) {
    // R = 1.6 steps about an off-grid centre with 25 chords: most ideal ends share a grid cell with their
    // neighbours, and the in-order corners of a cell may lie far off the circle. Such ends are left out rather
    // than zig-zag across the circle: what remains runs round once, never backwards, every end within half a
    // cell diagonal (Round's bound) of the circle.
    CamOptions opt;
    opt.chord_tolerance_mm = 0.0001;
    const auto segs = cam_of("G0 X0.016 Y0.01\nG2 I-0.01 J0 F600\n", opt);
    EXPECT_EQ(chord_count(0.01, 2 * M_PI, kOnArcSagittaShare * 0.0001), 25);
    ASSERT_EQ(segs.size(), 1u + 12u);
    const auto m = check_chords(arc_ends(segs), {0.006, 0.01}, 0.01, false, 1.0, M_PI);
    EXPECT_LE(m.max_residual_mm * kSpm, 0.5 * std::sqrt(2.0));
    EXPECT_NEAR(m.travelled_rad, -2 * M_PI, 1e-12);
}

TEST(HostCam, OnArcLargeRadius) {
    // R = 500 mm: W = 3 (the cap); 1242 chords.
    const double tol = CamOptions{}.chord_tolerance_mm;
    const auto segs = cam_of("G0 X500 Y0\nG2 I-500 F6000\n");
    EXPECT_EQ(chord_count(500.0, 2 * M_PI, kOnArcSagittaShare * tol), 1242);
    ASSERT_EQ(segs.size(), 1u + 1242u);
    const auto ends = arc_ends(segs);
    const auto m = check_chords(ends, {0, 0}, 500.0, false, tol, max_chord_rad(500.0, tol));
    // Every end its window's nearest (0.414 step at worst), within OnArc's half step; the longest span between
    // the mean and the tolerance's span.
    const double promised = expect_ends_nearest_in_window(ends, {0, 0}, 500.0, 0.0, -2 * M_PI, tol, kSpm, kSpm);
    EXPECT_DOUBLE_EQ(m.max_residual_mm, promised);
    EXPECT_LE(m.max_residual_mm, on_arc_bound_mm(kSpm, kSpm));
    EXPECT_GE(m.max_span_rad, 2 * M_PI / 1242);
    EXPECT_NEAR(m.travelled_rad, -2 * M_PI, 1e-12);
    EXPECT_DOUBLE_EQ(ends.back().x_mm, 500.0);
    EXPECT_DOUBLE_EQ(ends.back().y_mm, 0.0);
}

TEST(HostCam, CcwArcKeepsMotionCodeThree) {
    const auto segs = cam_of("G0 X10\nG3 X0 Y10 I-10 F600\n");
    ASSERT_EQ(segs.size(), 1u + 44u);  // chord_count(10, pi/2, 0.8 x 0.002)
    for (std::size_t i = 1; i < segs.size(); ++i) EXPECT_EQ(segs[i].motion, MotionKind::ArcCCW);
    const auto m = check_chords(arc_ends(segs), {0, 0}, 10.0, true, 0.002, max_chord_rad(10.0, 0.002));
    EXPECT_NEAR(m.travelled_rad, M_PI / 2, 1e-12);
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
    EXPECT_EQ(static_cast<std::int64_t>(cam_of("G0 X10\nG3 X0 Y10 I-10 F600\n", opt).size()),
              1 + chord_count(10.0, M_PI / 2, 0.08));
    EXPECT_EQ(chord_count(10.0, M_PI / 2, 0.08), 7);
    opt.chord_ends = ChordEnds::Round;
    EXPECT_EQ(static_cast<std::int64_t>(cam_of("G0 X10\nG3 X0 Y10 I-10 F600\n", opt).size()),
              1 + chord_count(10.0, M_PI / 2, 0.1));
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
    // 1600 steps on both axes: X is dominant on a tie (step_gen, seed 000 §5.2.4), though Y moves 20 mm to X's 10.
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
    MachineModel unlimited;  // axes fast enough that the packet range, not the machine, stops the feed
    unlimited.x.limits.max_velocity_mm_per_s = unlimited.y.limits.max_velocity_mm_per_s = 1e5;
    expect_bad_input([&] { cam_of("G1 X10 F70000\n", {}, unlimited); }, {"t.nc:1:", "feed 70000", "1..65535"});
    InterpreterOptions fast;
    fast.rapid_feed_mm_per_min = 100000.0;
    expect_bad_input([&] { cam(run_gcode("G0 X1\n", fast), unlimited, {}); }, {"t.nc:1:", "feed 100000"});
}

TEST(HostCam, FeedIsHeldToTheAxisVelocityLimits) {
    MachineModel m;
    m.x.limits.max_velocity_mm_per_s = 10.0;  // 600 mm/min
    m.y.limits.max_velocity_mm_per_s = 5.0;   // 300 mm/min
    // X alone at F1000: X's 600 mm/min. The 45-degree line at F1000 (707 mm/min per axis): Y's 300 mm/min
    // holds the path to 300 x sqrt(2) = 424.3 mm/min, whose dominant-axis share is 300 mm/min.
    const auto segs = cam_of("G1 X10 F1000\nG1 X20 Y10\nG1 X30 F500\n", {}, m);
    ASSERT_EQ(segs.size(), 3U);
    EXPECT_EQ(segs[0].feed, 600);
    EXPECT_EQ(segs[1].feed, 300);
    EXPECT_EQ(segs[2].feed, 500);  // below the limit: untouched
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

TEST(HostCam, EmptyProgramGivesNoSegments) {
    EXPECT_TRUE(cam_of("G21\n").empty());
}

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
