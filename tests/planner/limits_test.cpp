// Every sample of a mixed job (rapids, lines at odd angles, arcs, corners, reversals) within the axis limits,
// in every mode and profile; contour error within the tolerance; a long job.
#include <cmath>
#include <string>

#include "planner_test_util.hpp"

namespace cnc::host::planner {
namespace {

using geom::Vec2;
using test::config;
using test::contour_error;
using test::for_each_sample;
using test::gcode;

const char* const kMixedJob =
    "G0 X5 Y5\n"
    "G1 X25 Y5 F4800\n"
    "G1 X40 Y17\n"          // corner (38.7 deg)
    "G2 X50 Y27 I10 J0\n"   // corner into a clockwise quarter circle
    "G1 X50 Y40 F9000\n"    // corner out of the arc, faster feed
    "G3 X40 Y50 I-10 J0\n"  // tangent counter-clockwise arc
    "G1 X10 Y50\n"          // tangent line
    "G1 X10.3 Y49.2\n"      // sharp corner on a short move
    "G1 X10.3 Y30\n"
    "G1 X10.3 Y45\n"        // reversal
    "G3 X10.3 Y45 I3 J0\n"  // full circle at a corner
    "G2 X20 Y40 R6\n"
    "G0 X0 Y0\n";

struct Check {
    double v_max = 0.0;  // worst |v_axis| / v_limit
    double a_max = 0.0;  // worst |a_axis| / a_limit (analytic)
    double a_num = 0.0;  // worst |dv_axis/dt| / a_limit (finite differences)
    double v_num = 0.0;  // worst |dx_axis/dt| / v_limit (finite differences)
    double contour = 0.0;
};

Check check(const Program& p, const Trajectory& t, const PlannerConfig& cfg) {
    Check c;
    const double dt = 2e-5;
    Sample prev = t.at(0.0);
    for_each_sample(t, dt, [&](const Sample& s) {
        const double h = s.t_s - prev.t_s;
        c.v_max = std::max({c.v_max, std::fabs(s.vel_mm_per_s.x_mm) / cfg.x.max_velocity_mm_per_s,
                            std::fabs(s.vel_mm_per_s.y_mm) / cfg.y.max_velocity_mm_per_s});
        c.a_max = std::max({c.a_max, std::fabs(s.acc_mm_per_s2.x_mm) / cfg.x.max_accel_mm_per_s2,
                            std::fabs(s.acc_mm_per_s2.y_mm) / cfg.y.max_accel_mm_per_s2});
        if (h > 0.0) {
            const Vec2 dv = (s.vel_mm_per_s - prev.vel_mm_per_s) * (1.0 / h);
            const Vec2 dx = (s.pos_mm - prev.pos_mm) * (1.0 / h);
            c.a_num = std::max({c.a_num, std::fabs(dv.x_mm) / cfg.x.max_accel_mm_per_s2,
                                std::fabs(dv.y_mm) / cfg.y.max_accel_mm_per_s2});
            c.v_num = std::max({c.v_num, std::fabs(dx.x_mm) / cfg.x.max_velocity_mm_per_s,
                                std::fabs(dx.y_mm) / cfg.y.max_velocity_mm_per_s});
        }
        c.contour = std::max(c.contour, contour_error(p, s.pos_mm));
        prev = s;
    });
    return c;
}

TEST(PlannerLimits, MixedJobWithinAxisLimitsEverywhere) {
    const Program p = gcode(kMixedJob, test::kRapidAboveTheAxes_mm_per_min);
    for (BlendMode mode : {BlendMode::ExactStop, BlendMode::Continuous}) {
        for (Profile profile : {Profile::Trapezoidal, Profile::JerkLimited}) {
            PlannerConfig cfg = config(mode, profile);
            cfg.y.max_velocity_mm_per_s = 70.0;
            cfg.y.max_accel_mm_per_s2 = 600.0;
            cfg.y.max_jerk_mm_per_s3 = 30000.0;
            const Trajectory t = plan(p, cfg);
            const Check c = check(p, t, cfg);
            const std::string tag = std::string(mode == BlendMode::ExactStop ? "G61 " : "G64 ") +
                                    (profile == Profile::Trapezoidal ? "trapezoid" : "jerk");
            EXPECT_LE(c.v_max, 1.0 + 1e-9) << tag;
            EXPECT_LE(c.a_max, 1.0 + 1e-9) << tag;
            EXPECT_LE(c.v_num, 1.0 + 1e-6) << tag;
            EXPECT_LE(c.a_num, 1.0 + 1e-3) << tag;
            EXPECT_GT(c.v_max, 0.9) << tag;  // the limits are reached, so the checks have teeth
            EXPECT_GT(c.a_max, 0.9) << tag;
            EXPECT_LE(c.contour, (mode == BlendMode::ExactStop ? 1e-9 : cfg.path_tolerance_mm + 1e-9)) << tag;
            const Sample end = t.at(t.duration_s());
            EXPECT_EQ(end.pos_mm.x_mm, 0.0) << tag;
            EXPECT_EQ(end.pos_mm.y_mm, 0.0) << tag;
        }
    }
}

TEST(PlannerLimits, PiecesJoinAndMoveWindowsAreOrdered) {
    const Program p = gcode(kMixedJob, test::kRapidAboveTheAxes_mm_per_min);
    const Trajectory t = plan(p, config(BlendMode::Continuous));
    const auto& pieces = t.pieces();
    int blends = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        if (pieces[k].move < 0) ++blends;
        if (k == 0) continue;
        EXPECT_LE(geom::distance(pieces[k - 1].path.end, pieces[k].path.start), 1e-12) << k;
        EXPECT_EQ(pieces[k - 1].t_end_s, pieces[k].t_begin_s);
        EXPECT_EQ(pieces[k - 1].speed.exit_mm_per_s, pieces[k].speed.entry_mm_per_s);
    }
    EXPECT_GE(blends, 5);
    const auto& w = t.move_windows();
    ASSERT_EQ(w.size(), p.moves.size());
    for (std::size_t i = 0; i < w.size(); ++i) {
        EXPECT_LT(w[i].first, w[i].second) << i;
        if (i > 0) {
            EXPECT_LE(w[i - 1].second, w[i].first) << i;
        }
    }
}

TEST(PlannerLimits, HundredThousandMoveZigzag) {
    // 10^5 moves of 0.5 mm alternating +-30 degrees: every join is blended; planning is O(moves * window).
    Program p;
    p.filename = "zigzag";
    Vec2 at{};
    for (int i = 0; i < 100000; ++i) {
        const Vec2 next = at + Vec2{0.5 * std::cos(M_PI / 6), (i % 2 == 0 ? 0.5 : -0.5) * std::sin(M_PI / 6)};
        p.moves.push_back(ProgrammedMove{MotionKind::Linear, geom::Segment::line(at, next), 3000.0, true, i + 1});
        at = next;
    }
    const Trajectory t = plan(p, config(BlendMode::Continuous));
    EXPECT_EQ(t.pieces().size(), 2u * 100000u - 1u);
    EXPECT_NEAR(t.at(t.duration_s()).pos_mm.x_mm, at.x_mm, 1e-9);
    // At the join speed the whole job takes its length over a steady speed plus the two ends.
    const double v_join = t.pieces()[100001].speed.entry_mm_per_s;
    EXPECT_GT(v_join, 1.0);
    EXPECT_LE(v_join, 50.0);
    const double mid = 0.5 * t.duration_s();
    EXPECT_GT(t.at(mid).path_speed_mm_per_s, 0.5 * v_join);
}

}  // namespace
}  // namespace cnc::host::planner
