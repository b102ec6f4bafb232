// Soft limits: every programmed move, arcs by the extremes they pass through, against [0, travel_mm].
#include <gtest/gtest.h>

#include "host/core/soft_limits.hpp"
#include "host_test_util.hpp"

namespace cnc::host {
namespace {

using geom::Segment;
using test::bad_input_message;
using test::expect_bad_input;

ProgrammedMove move(const Segment& path, int line) {
    return {MotionKind::Linear, path, 600.0, true, line};
}

MachineModel machine_with_travel(double x_mm, double y_mm) {
    MachineModel m;
    m.x.travel_mm = x_mm;
    m.y.travel_mm = y_mm;
    return m;
}

TEST(HostSoftLimits, InchMoveOnA10mmAxisNamesLineAxisValueAndKey) {
    Program p{"job.nc", {move(Segment::line({0, 0}, {5, 5}), 2), move(Segment::line({5, 5}, {25.4, 5}), 3)}};
    EXPECT_EQ(bad_input_message([&] { check_soft_limits(p, machine_with_travel(10, 10)); }),
              "job.nc:3: X 25.4 mm is past machine.x.travel_mm = 10 (soft limits; machine.soft_limits = false "
              "turns them off)");
}

TEST(HostSoftLimits, BelowZeroIsOutsideToo) {
    Program p{"job.nc", {move(Segment::line({2, 2}, {2, -0.5}), 7)}};
    expect_bad_input([&] { check_soft_limits(p, machine_with_travel(10, 10)); },
                     {"job.nc:7: Y -0.5 mm is below 0", "machine.y.travel_mm = 10"});
}

TEST(HostSoftLimits, MovesOnTheTravelEndsAreInside) {
    Program p{"job.nc", {move(Segment::line({0, 0}, {10, 10}), 1), move(Segment::line({10, 10}, {0, 0}), 2)}};
    EXPECT_NO_THROW(check_soft_limits(p, machine_with_travel(10, 10)));
}

TEST(HostSoftLimits, ArcIsCheckedAtItsExtremeNotOnlyAtItsEnds) {
    // Half circle of radius 4 about (5, 5) from (1, 5) to (9, 5): both ends at Y 5, but clockwise it passes
    // over the top through (5, 9), counter-clockwise under the bottom through (5, 1).
    const Program cw{"arc.nc", {move(Segment::arc({1, 5}, {9, 5}, {5, 5}, false), 4)}};
    expect_bad_input([&] { check_soft_limits(cw, machine_with_travel(10, 8)); },
                     {"arc.nc:4: Y 9 mm is past machine.y.travel_mm = 8"});
    const Program ccw{"arc.nc", {move(Segment::arc({1, 5}, {9, 5}, {5, 5}, true), 4)}};
    EXPECT_NO_THROW(check_soft_limits(ccw, machine_with_travel(10, 8)));
}

TEST(HostSoftLimits, FullCircleReachesAllFourSides) {
    const Program p{"c.nc", {move(Segment::arc({6, 3}, {6, 3}, {3, 3}, true), 1)}};  // r 3 about (3, 3)
    EXPECT_NO_THROW(check_soft_limits(p, machine_with_travel(6, 6)));
    expect_bad_input([&] { check_soft_limits(p, machine_with_travel(6, 5.9)); }, {"Y 6 mm is past"});
}

TEST(HostSoftLimits, OffOrUnlimitedAxesAreNotChecked) {
    const Program p{"job.nc", {move(Segment::line({0, 0}, {-5, 400}), 1)}};
    EXPECT_NO_THROW(check_soft_limits(p, machine_with_travel(0, 0)));  // travel 0: unlimited
    MachineModel off = machine_with_travel(10, 10);
    off.soft_limits = false;
    EXPECT_NO_THROW(check_soft_limits(p, off));
    expect_bad_input([&] { check_soft_limits(p, machine_with_travel(0, 300)); }, {"Y 400 mm"});
}

TEST(HostSoftLimits, BreachOfOnePosition) {
    const MachineModel m = machine_with_travel(10, 20);
    EXPECT_FALSE(soft_limit_breach(m, MachineAxis::X, 10, 10));
    EXPECT_EQ(soft_limit_breach(m, MachineAxis::Y, 21, 21).value_or(""),
              "Y 21 mm is past machine.y.travel_mm = 20 (soft limits; machine.soft_limits = false turns them off)");
}

}  // namespace
}  // namespace cnc::host
