// seed 003 §5.1.2's alignment loop: its three-line example, the exact float comparisons and the revision limit.
#include <gtest/gtest.h>

#include <cmath>

#include "cam/dxf_reader.hpp"
#include "cam/ordering.hpp"
#include "cam/route_stats.hpp"
#include "dxf_text.hpp"
#include "support/test_path.hpp"

namespace cnc::cam {
namespace {

Entity line(double x1, double y1, double x2, double y2) {
    Entity e;
    e.path = geom::Segment::line({x1, y1}, {x2, y2});
    e.type = "LINE";
    return e;
}

// L1 (10,10)->(10,30), L2 (30,40)->(50,40), L3 (10,30)->(30,40), drawn in that order.
std::vector<Entity> three_lines() {
    const std::string path = test::test_path("three_lines.dxf");
    test::DxfText().line(10, 10, 10, 30).line(30, 40, 50, 40).line(10, 30, 30, 40).write(path);
    return read_dxf(path, {}).entities;
}

TEST(CamSeed003, ThreeLineExampleGivesL1L3L2WithFourCommandsAndOneCycle) {
    const std::vector<Entity> e = three_lines();
    const std::vector<Route> routes = order_routes(e, Order::Seed003, {});
    ASSERT_EQ(routes.size(), 1u);
    ASSERT_EQ(routes[0].size(), 3u);
    EXPECT_EQ(routes[0][0].entity, 0);
    EXPECT_EQ(routes[0][1].entity, 2);
    EXPECT_EQ(routes[0][2].entity, 1);
    for (const Step& s : routes[0]) EXPECT_FALSE(s.reversed);
    const RouteStats st = route_stats(e, routes, {0, 0});
    EXPECT_EQ(st.commands(), 4);  // G00 to (10,10), then three G01
    EXPECT_EQ(st.routes, 1);      // one head on/off cycle
}

TEST(CamSeed003, ThreeLineExampleInDrawingOrderNeedsSixCommandsAndThreeCycles) {
    const std::vector<Entity> e = three_lines();
    const RouteStats st = route_stats(e, order_routes(e, Order::Selection, {}), {0, 0});
    EXPECT_EQ(st.commands(), 6);
    EXPECT_EQ(st.routes, 3);
}

// Case 1 (a shared end) reverses the later entity; case 2 (a shared start) reverses it and puts it first.
TEST(CamSeed003, SharedEndsAndStartsAreTurnedRound) {
    const std::vector<Entity> ends = {line(0, 0, 10, 0), line(20, 0, 10, 0)};
    const std::vector<Step> a = seed003_sequence(ends, std::nullopt);
    EXPECT_EQ(a[0].entity, 0);
    EXPECT_EQ(a[1].entity, 1);
    EXPECT_TRUE(a[1].reversed);
    const std::vector<Entity> starts = {line(10, 0, 20, 0), line(10, 0, 0, 0)};
    const std::vector<Step> b = seed003_sequence(starts, std::nullopt);
    EXPECT_EQ(b[0].entity, 1);
    EXPECT_TRUE(b[0].reversed);
    EXPECT_EQ(b[1].entity, 0);
    EXPECT_EQ(route_stats(starts, order_routes(starts, Order::Seed003, {}), {0, 0}).routes, 1);
}

// The seed compares float fields with ==: a line typed to three decimals does not meet an arc's computed end
// (60 degrees on radius 10: (5, 8.6602540...)), and the G-code gets a G00 there; a tolerance joins them.
TEST(CamSeed003, ExactFloatComparisonsBreakAtAnArcsComputedEnd) {
    const std::string path = test::test_path("arc_line.dxf");
    test::DxfText().arc(0, 0, 10, 0, 60).line(5, 8.66, -5, 8.66).write(path);
    const std::vector<Entity> e = read_dxf(path, {}).entities;
    OrderOptions exact;
    EXPECT_EQ(order_routes(e, Order::Seed003, exact).size(), 2u);
    OrderOptions fixed;
    fixed.seed003_tolerance_mm = 0.001;
    EXPECT_EQ(order_routes(e, Order::Seed003, fixed).size(), 1u);
}

// A closed triangle drawn head to tail keeps case 3 firing on every revision: the loop stops at 100, with every
// entity still there once.
TEST(CamSeed003, ALoopThatNeverSettlesStopsAtTheRevisionLimit) {
    const std::vector<Entity> e = {line(0, 0, 10, 0), line(10, 0, 0, 10), line(0, 10, 0, 0)};
    const std::vector<Step> s = seed003_sequence(e, std::nullopt);
    ASSERT_EQ(s.size(), 3u);
    std::vector<int> seen;
    for (const Step& st : s) seen.push_back(st.entity);
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(seen, (std::vector<int>{0, 1, 2}));
}

}  // namespace
}  // namespace cnc::cam
