// Geometry the planner follows (curve.hpp) and the line-line corner blend (corner_blend.hpp).
#include <cmath>
#include <limits>

#include "host/core/planner/corner_blend.hpp"
#include "host/core/planner/curve.hpp"
#include "planner_test_util.hpp"

namespace cnc::host::planner {
namespace {

using geom::Vec2;

constexpr double kPi = 3.141592653589793;

void expect_point(Vec2 p, double x_mm, double y_mm, double tol = 1e-12) {
    EXPECT_NEAR(p.x_mm, x_mm, tol);
    EXPECT_NEAR(p.y_mm, y_mm, tol);
}

TEST(PlannerCurve, CircleArcStaysOnTheCircle) {
    const Curve c = Curve::arc({10, 0}, {0, 10}, {0, 0}, kPi / 2);
    EXPECT_NEAR(c.length_mm(), 5 * kPi, 1e-12);
    for (int i = 0; i <= 100; ++i) {
        const Vec2 p = c.point_at(c.length_mm() * i / 100.0);
        EXPECT_NEAR(geom::norm(p), 10.0, 1e-12);
    }
    expect_point(c.point_at(0.0), 10, 0);
    expect_point(c.point_at(c.length_mm() / 2), 10 / std::sqrt(2.0), 10 / std::sqrt(2.0));
    expect_point(c.unit_tangent_at(0.0), 0, 1);
    expect_point(c.second_derivative(0.0), -0.1, 0);  // 1/R towards the centre
    EXPECT_DOUBLE_EQ(c.max_stretch(), 1.0);
}

TEST(PlannerCurve, SpiralJoinsTheProgrammedEndPoint) {
    // The interpreter allows the end 0.01 mm off the start circle; the planner's arc ends exactly there.
    const Program p = test::gcode("G1 X10 F600\nG3 X0 Y10.008 I-10 J0\n");
    const Curve c = Curve::from_segment(p.moves[1].path);
    expect_point(c.point_at(0.0), 10, 0, 0.0);
    expect_point(c.point_at(c.length_mm()), 0, 10.008, 0.0);
    expect_point(c.point_at(c.length_mm() * (1.0 - 1e-12)), 0, 10.008, 1e-9);
    // Curvature halfway between 1/10 and 1/10.008 at the middle; radius slope 0 and unit speed at both ends.
    EXPECT_NEAR(geom::norm(c.point_at(c.length_mm() / 2)), 2 * 10 * 10.008 / 20.008, 1e-12);
    for (double s_end : {0.0, c.length_mm()}) {
        const Vec2 d = c.first_derivative(s_end);
        EXPECT_NEAR(geom::norm(d), 1.0, 1e-12);
        EXPECT_NEAR(geom::dot(d, unit(c.point_at(s_end))), 0.0, 1e-12);  // along the end circle's tangent
    }
    // The derivative matches the finite difference of positions.
    const double s = 3.0;
    const double h = 1e-6;
    const Vec2 fd = (c.point_at(s + h) - c.point_at(s - h)) * (0.5 / h);
    const Vec2 d1 = c.first_derivative(s);
    EXPECT_NEAR(fd.x_mm, d1.x_mm, 1e-8);
    EXPECT_NEAR(fd.y_mm, d1.y_mm, 1e-8);
    const Vec2 fd2 = (c.first_derivative(s + h) - c.first_derivative(s - h)) * (0.5 / h);
    const Vec2 d2 = c.second_derivative(s);
    EXPECT_NEAR(fd2.x_mm, d2.x_mm, 1e-7);
    EXPECT_NEAR(fd2.y_mm, d2.y_mm, 1e-7);
    EXPECT_LE(geom::norm(d2), c.max_curvature_per_mm());
    EXPECT_GT(c.max_stretch(), 1.0);
}

TEST(PlannerCurve, CutKeepsTheCentre) {
    const Curve c = Curve::arc({10, 0}, {-10, 0}, {0, 0}, kPi);
    const Curve cut = c.cut_start({0, 10}).cut_end({-10 / std::sqrt(2.0), 10 / std::sqrt(2.0)});
    EXPECT_NEAR(cut.sweep_rad, kPi / 4, 1e-15);
    EXPECT_NEAR(cut.length_mm(), 10 * kPi / 4, 1e-12);
    const Curve line = Curve::line({0, 0}, {10, 0}).cut_start({2, 0}).cut_end({7, 0});
    EXPECT_DOUBLE_EQ(line.length_mm(), 5.0);
}

// A goal speed no corner reaches: the blend keeps the largest radius its tolerance allows (LinuxCNC's radius is
// then sqrt(a_n R_geom)^2 / a_n = R_geom).
constexpr double kAnySpeed = std::numeric_limits<double>::infinity();
constexpr double kAccel = 1000.0;

TEST(PlannerBlend, RightAngleClosedForm) {
    // h = 45 deg: R = tol cos(h) / (1 - cos(h)) = 0.05 * 0.7071 / 0.2929 = 0.120711 mm, tangent length R tan(h).
    const auto b = corner_blend(Curve::line({0, 0}, {20, 0}), Curve::line({20, 0}, {20, 20}), 0.05, kAnySpeed, kAccel);
    ASSERT_TRUE(b.has_value());
    const double r = 0.05 * std::cos(kPi / 4) / (1 - std::cos(kPi / 4));
    EXPECT_NEAR(b->start_radius_mm(), r, 1e-12);
    expect_point(b->start, 20 - r, 0);
    expect_point(b->end, 20, r);
    expect_point(b->center, 20 - r, r);
    EXPECT_NEAR(b->sweep_rad, kPi / 2, 1e-15);
    EXPECT_NEAR(b->segment().distance_to({20, 0}), 0.05, 1e-12);
}

TEST(PlannerBlend, ShortMovesLimitTheRadiusToHalfTheirLength) {
    // 0.1 mm moves: the tangent length may not exceed 0.05 mm, so R = 0.05 / tan(45 deg) and the
    // deviation 0.05 (sqrt(2) - 1) = 0.0207 mm stays under the 0.05 mm tolerance.
    const auto b =
        corner_blend(Curve::line({0, 0}, {0.1, 0}), Curve::line({0.1, 0}, {0.1, -0.1}), 0.05, kAnySpeed, kAccel);
    ASSERT_TRUE(b.has_value());
    EXPECT_NEAR(b->start_radius_mm(), 0.05, 1e-15);
    EXPECT_NEAR(b->sweep_rad, -kPi / 2, 1e-15);  // right turn: clockwise
    EXPECT_NEAR(b->segment().distance_to({0.1, 0}), 0.05 * (std::sqrt(2.0) - 1), 1e-12);
}

TEST(PlannerBlend, NoBlendForZeroToleranceOrReversal) {
    const Curve a = Curve::line({0, 0}, {10, 0});
    EXPECT_FALSE(corner_blend(a, Curve::line({10, 0}, {10, 10}), 0.0, kAnySpeed, kAccel).has_value());
    EXPECT_FALSE(corner_blend(a, Curve::line({10, 0}, {0, 0}), 0.05, kAnySpeed, kAccel).has_value());
}

// LinuxCNC blendmath.c blendComputeParameters, by hand. A 90 degree corner of 20 mm lines, tolerance 5 mm
// (G64 without P: a quarter of a line), goal 50 mm/s, A = 1000 mm/s^2: R_geom = 10 mm (half a line),
// v = min(sqrt(866 * 10), 50) = 50, t = min(sqrt(1000 * 10), 50) / 500 = 0.1 s, R = max(2500 / 866,
// min(0.1 * 50 / (pi/2), 10)) = 3.183 mm, which LinuxCNC 2.9 cuts (its path 1.3186 mm from the corner, halsampler
// data of tests/data/linuxcnc_planner, x1_square_g64). At P0.05 (R_geom 0.1207) the corner is tolerance-bound.
TEST(PlannerBlend, RadiusAsLinuxCncPlansIt) {
    const Curve a = Curve::line({0, 0}, {20, 0});
    const Curve b = Curve::line({20, 0}, {20, 20});
    const auto quarter = corner_blend(a, b, 5.0, 50.0, kAccel);
    ASSERT_TRUE(quarter.has_value());
    EXPECT_NEAR(quarter->start_radius_mm(), 0.1 * 50.0 / (kPi / 2), 1e-12);
    EXPECT_NEAR(quarter->segment().distance_to({20, 0}), 1.3186, 5e-4);  // sampled every 1 ms at 50 mm/s
    const auto tight = corner_blend(a, b, 0.05, 50.0, kAccel);
    ASSERT_TRUE(tight.has_value());
    EXPECT_NEAR(tight->start_radius_mm(), 0.05 * std::cos(kPi / 4) / (1 - std::cos(kPi / 4)), 1e-12);
}

TEST(PlannerBlend, LineIntoArcCorner) {
    // Line along +x into a clockwise semicircle whose tangent at the start is +y: a 90 degree corner.
    const Curve a = Curve::line({0, 0}, {10, 0});
    const Curve b = Curve::arc({10, 0}, {20, 0}, {15, 0}, -kPi);
    const auto blend = corner_blend(a, b, 0.05, kAnySpeed, kAccel);
    ASSERT_TRUE(blend.has_value());
    EXPECT_NEAR(blend->start.y_mm, 0.0, 1e-12);                   // on the line
    EXPECT_NEAR(geom::distance(blend->end, {15, 0}), 5.0, 1e-9);  // on the circle
    EXPECT_LE(blend->segment().distance_to({10, 0}), 0.05 + 1e-12);
    EXPECT_GT(blend->segment().distance_to({10, 0}), 0.04);                  // close to the tolerance
    EXPECT_NEAR(geom::dot(blend->unit_tangent_at(0.0), {1, 0}), 1.0, 1e-9);  // tangent to the line
    const Vec2 radial = unit(blend->end - Vec2{15, 0});
    EXPECT_NEAR(geom::dot(blend->unit_tangent_at(blend->length_mm()), {radial.y_mm, -radial.x_mm}), 1.0, 1e-9);
}

}  // namespace
}  // namespace cnc::host::planner
