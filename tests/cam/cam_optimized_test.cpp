// Our ordering against seed 000's on generated drawings (a fixed seed): never more rapid length, and less on a
// scattered one; every entity cut once, each route still a chain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include <fmt/format.h>

#include "cam/ordering.hpp"
#include "cam/route_stats.hpp"

namespace cnc::cam {
namespace {

constexpr double kTolMm = 0.001;

Entity entity(const geom::Segment& s) {
    Entity e;
    e.path = s;
    e.type = s.is_arc ? "ARC" : "LINE";
    return e;
}

// Closed squares (drawn with random edge directions), circles and loose lines over a 300 x 200 mm sheet.
std::vector<Entity> generated(std::mt19937& rng, int shapes) {
    std::uniform_real_distribution<double> x(0, 300), y(0, 200), size(2, 20), coin(0, 1);
    std::vector<Entity> out;
    for (int k = 0; k < shapes; ++k) {
        const geom::Vec2 at{x(rng), y(rng)};
        const double s = size(rng);
        const double kind = coin(rng);
        if (kind < 0.4) {
            const geom::Vec2 c[4] = {at, {at.x_mm + s, at.y_mm}, {at.x_mm + s, at.y_mm + s}, {at.x_mm, at.y_mm + s}};
            for (int i = 0; i < 4; ++i) {
                const geom::Vec2 a = c[i], b = c[(i + 1) % 4];
                out.push_back(entity(coin(rng) < 0.5 ? geom::Segment::line(a, b) : geom::Segment::line(b, a)));
            }
        } else if (kind < 0.7) {
            const geom::Vec2 from{at.x_mm + s, at.y_mm};
            out.push_back(entity(geom::Segment::arc(from, from, at, true)));
        } else {
            out.push_back(entity(geom::Segment::line(at, {x(rng), y(rng)})));
        }
    }
    std::shuffle(out.begin(), out.end(), rng);
    return out;
}

void expect_valid(const std::vector<Entity>& e, const std::vector<Route>& routes) {
    std::vector<int> seen;
    for (const Route& r : routes) {
        for (std::size_t k = 0; k < r.size(); ++k) {
            seen.push_back(r[k].entity);
            if (k > 0) {
                EXPECT_LE(geom::distance(step_path(e, r[k - 1]).end, step_path(e, r[k]).start), kTolMm);
            }
        }
    }
    std::sort(seen.begin(), seen.end());
    for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], static_cast<int>(i));
    EXPECT_EQ(seen.size(), e.size());
}

TEST(CamOptimized, NeverMoreRapidLengthThanSeed000) {
    std::mt19937 rng(20260101);
    for (int drawing = 0; drawing < 12; ++drawing) {
        const std::vector<Entity> e = generated(rng, 5 + 5 * drawing);
        const std::vector<Route> seed = order_routes(e, Order::Seed000, {});
        const std::vector<Route> ours = order_routes(e, Order::Optimized, {});
        expect_valid(e, ours);
        const RouteStats a = route_stats(e, seed, {0, 0});
        const RouteStats b = route_stats(e, ours, {0, 0});
        std::cout << fmt::format(FMT_STRING("drawing {:2d}: {:3d} entities, {:3d} routes: rapids seed000 {:8.1f} mm, "
                                            "optimized {:8.1f} mm\n"),
                                 drawing, e.size(), a.routes, a.rapid_mm, b.rapid_mm);
        EXPECT_LE(b.rapid_mm, a.rapid_mm + 1e-9) << "drawing " << drawing;
        EXPECT_EQ(b.routes, a.routes);  // the same chains: as many laser cycles
        EXPECT_NEAR(b.cut_mm, a.cut_mm, 1e-9);
    }
}

// 40 circles scattered over the sheet: seed000 visits them by smallest x, zigzagging in y; a tour does better.
TEST(CamOptimized, ScatteredDrawingHasShorterRapids) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> x(0, 300), y(0, 200);
    std::vector<Entity> e;
    for (int k = 0; k < 40; ++k) {
        const geom::Vec2 c{x(rng), y(rng)};
        e.push_back(entity(geom::Segment::arc({c.x_mm + 3, c.y_mm}, {c.x_mm + 3, c.y_mm}, c, true)));
    }
    const double seed = route_stats(e, order_routes(e, Order::Seed000, {}), {0, 0}).rapid_mm;
    const std::vector<Route> ours = order_routes(e, Order::Optimized, {});
    expect_valid(e, ours);
    const double mine = route_stats(e, ours, {0, 0}).rapid_mm;
    std::cout << fmt::format(FMT_STRING("40 scattered circles: rapids seed000 {:.1f} mm, optimized {:.1f} mm "
                                        "({:.0f} %)\n"),
                             seed, mine, 100.0 * mine / seed);
    EXPECT_LT(mine, 0.8 * seed);
}

}  // namespace
}  // namespace cnc::cam
