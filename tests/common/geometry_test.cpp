#include <gtest/gtest.h>

#include <cmath>

#include "common/geometry.hpp"

using cnc::geom::Segment;
using cnc::geom::Vec2;

TEST(Geometry, LineLengthPointAndDistance) {
    const Segment s = Segment::line({0, 0}, {10, 5});
    EXPECT_DOUBLE_EQ(s.length_mm(), std::sqrt(125.0));
    const Vec2 mid = s.point_at(s.length_mm() / 2);
    EXPECT_DOUBLE_EQ(mid.x_mm, 5.0);
    EXPECT_DOUBLE_EQ(mid.y_mm, 2.5);
    EXPECT_NEAR(s.distance_to({0, 5}), 5.0 * 10.0 / std::sqrt(125.0), 1e-12);
    EXPECT_DOUBLE_EQ(s.distance_to({-3, -4}), 5.0);  // beyond the start: distance to the endpoint
}

TEST(Geometry, FullCircleIsTwoPiEitherWay) {
    const Segment ccw = Segment::arc({10, 0}, {10, 0}, {0, 0}, true);
    const Segment cw = Segment::arc({10, 0}, {10, 0}, {0, 0}, false);
    EXPECT_NEAR(ccw.length_mm(), 2 * M_PI * 10, 1e-9);
    EXPECT_NEAR(cw.sweep_rad, -2 * M_PI, 1e-12);
    const Vec2 quarter = ccw.point_at(ccw.length_mm() / 4);
    EXPECT_NEAR(quarter.x_mm, 0.0, 1e-9);
    EXPECT_NEAR(quarter.y_mm, 10.0, 1e-9);
    EXPECT_NEAR(cw.point_at(cw.length_mm() / 4).y_mm, -10.0, 1e-9);
    EXPECT_NEAR(ccw.distance_to({0, 9.99}), 0.01, 1e-9);
}

TEST(Geometry, ArcDistanceOutsideSweepGoesToNearestEnd) {
    // Quarter arc CCW from (10,0) to (0,10): the point (0,-10) is outside the sweep.
    const Segment q = Segment::arc({10, 0}, {0, 10}, {0, 0}, true);
    EXPECT_NEAR(q.sweep_rad, M_PI / 2, 1e-12);
    EXPECT_NEAR(q.distance_to({0, -10}), std::hypot(10.0, 10.0), 1e-9);
    EXPECT_NEAR(q.distance_to({7.0710678, 7.0710678}), 0.0, 1e-6);
    // The same end points clockwise sweep three quarters and do contain (0,-10).
    const Segment big = Segment::arc({10, 0}, {0, 10}, {0, 0}, false);
    EXPECT_NEAR(big.sweep_rad, -1.5 * M_PI, 1e-12);
    EXPECT_NEAR(big.distance_to({0, -10}), 0.0, 1e-9);
}

TEST(Geometry, BoundsOfALineAreItsEnds) {
    const cnc::geom::Box b = Segment::line({3, -1}, {-2, 4}).bounds();
    EXPECT_DOUBLE_EQ(b.min.x_mm, -2.0);
    EXPECT_DOUBLE_EQ(b.min.y_mm, -1.0);
    EXPECT_DOUBLE_EQ(b.max.x_mm, 3.0);
    EXPECT_DOUBLE_EQ(b.max.y_mm, 4.0);
}

TEST(Geometry, BoundsOfAnArcHoldTheAxisCrossingsItSweeps) {
    // Half circle about (10, 0) of radius 10 from (0, 0) to (20, 0): counter-clockwise it dips to (10, -10),
    // clockwise it rises to (10, 10).
    const cnc::geom::Box under = Segment::arc({0, 0}, {20, 0}, {10, 0}, true).bounds();
    EXPECT_DOUBLE_EQ(under.min.x_mm, 0.0);
    EXPECT_DOUBLE_EQ(under.max.x_mm, 20.0);
    EXPECT_NEAR(under.min.y_mm, -10.0, 1e-12);
    EXPECT_NEAR(under.max.y_mm, 0.0, 1e-12);
    const cnc::geom::Box over = Segment::arc({0, 0}, {20, 0}, {10, 0}, false).bounds();
    EXPECT_NEAR(over.min.y_mm, 0.0, 1e-12);
    EXPECT_NEAR(over.max.y_mm, 10.0, 1e-12);
    // Three quarters clockwise from (10, 0) to (0, 10) about the origin: through (0, -10) and (-10, 0).
    const cnc::geom::Box big = Segment::arc({10, 0}, {0, 10}, {0, 0}, false).bounds();
    EXPECT_NEAR(big.min.x_mm, -10.0, 1e-12);
    EXPECT_NEAR(big.min.y_mm, -10.0, 1e-12);
    EXPECT_NEAR(big.max.x_mm, 10.0, 1e-12);
    EXPECT_NEAR(big.max.y_mm, 10.0, 1e-12);
}
