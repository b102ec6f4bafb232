// The statistics across seeds, the records a rerun reads to skip the points done, and the search's bisection.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sweep/sweep_points.hpp"
#include "sweep/sweep_search.hpp"
#include "sweep/sweep_stats.hpp"

TEST(SweepStats, MeanExtremesAndStudentInterval) {
    // 1 .. 5: mean 3, sample standard deviation sqrt(2.5); t(0.975, 4) = 2.776 (any t table), so the half width is
    // 2.776 x sqrt(2.5) / sqrt(5) = 1.96293.
    const cnc::sim::SeedStats s = cnc::sim::seed_stats({5.0, 1.0, 4.0, 2.0, 3.0});
    EXPECT_EQ(s.n, 5u);
    EXPECT_DOUBLE_EQ(s.mean, 3.0);
    EXPECT_EQ(s.min, 1.0);
    EXPECT_EQ(s.max, 5.0);
    EXPECT_NEAR(s.half_width_95, 2.776 * std::sqrt(2.5) / std::sqrt(5.0), 1e-12);
    const cnc::sim::SeedStats one = cnc::sim::seed_stats({7.0});
    EXPECT_EQ(one.half_width_95, 0.0);
    EXPECT_EQ(one.mean, 7.0);
}

TEST(SweepStats, TQuantileBeyondTheTable) {
    // Exact values (scipy.stats.t.ppf(0.975, dof)): 40 -> 2.021075, 100 -> 1.983972, 1000 -> 1.962339.
    EXPECT_NEAR(cnc::sim::t_975(40), 2.021075, 1e-4);
    EXPECT_NEAR(cnc::sim::t_975(100), 1.983972, 1e-4);
    EXPECT_NEAR(cnc::sim::t_975(1000), 1.962339, 1e-4);
    EXPECT_DOUBLE_EQ(cnc::sim::t_975(1), 12.706);
    EXPECT_DOUBLE_EQ(cnc::sim::t_975(30), 2.042);
}

TEST(SweepRecord, ARerunSkipsAPointOnlyWithItsOwnSets) {
    cnc::sim::SweepPoint p;
    p.sets = {"scenario.architecture=a", "k.x=1"};
    const cnc::sim::PointRecord r{p.sets, 1, "cncsim: run failed: ack timeout"};
    const std::optional<cnc::sim::PointRecord> back = cnc::sim::parse_record(cnc::sim::record_json(r).dump());
    ASSERT_TRUE(back);
    EXPECT_EQ(back->exit_code, 1);
    EXPECT_EQ(back->message, r.message);
    EXPECT_TRUE(cnc::sim::point_done(p, back));
    cnc::sim::SweepPoint changed = p;
    changed.sets.back() = "k.x=2";  // the sweep file changed since: the same index, other values
    EXPECT_FALSE(cnc::sim::point_done(changed, back));
    EXPECT_FALSE(cnc::sim::point_done(p, std::nullopt));
    EXPECT_FALSE(cnc::sim::parse_record("{\"sets\": [\"a\"], \"exit_"));  // cut short
    EXPECT_FALSE(cnc::sim::parse_record("{\"sets\": [1], \"exit_code\": 0, \"message\": \"\"}"));
}

TEST(SweepRecord, FailureMessageIsTheLastLineOnStderr) {
    EXPECT_EQ(cnc::sim::failure_message("progress\ncncsim: run failed: x\n\n", 1), "cncsim: run failed: x");
    EXPECT_EQ(cnc::sim::failure_message("", 3), "exit code 3, nothing on stderr");
}

namespace {

// The bisection against a condition that holds up to `limit`: the values tried and the answer.
cnc::sim::Bisection search_up_to(double limit, double from, double to, double tolerance) {
    cnc::sim::Bisection b(from, to, tolerance);
    for (int guard = 0; guard < 100 && b.next(); ++guard) b.record(*b.next() <= limit);
    return b;
}

}  // namespace

TEST(SweepSearch, BisectionEndsOnTheGridAroundTheLimit) {
    // Holding up to 2650 on the grid 0, 60, 120, ...: the largest grid value that holds is 44 x 60 = 2640, the next
    // one, 2700, fails; at most log2(4800 / 60) + 2 values are tried.
    const cnc::sim::Bisection b = search_up_to(2650.0, 0.0, 4800.0, 60.0);
    EXPECT_EQ(b.good(), 2640.0);
    ASSERT_TRUE(b.bad());
    EXPECT_EQ(*b.bad(), 2700.0);
    EXPECT_TRUE(b.any_held());
    EXPECT_LE(b.tried().size(), 9u);
    EXPECT_EQ(b.tried().front(), std::make_pair(4800.0, false));  // `to` first
    for (const auto& [v, holds] : b.tried()) {
        EXPECT_EQ(std::fmod(v, 60.0), 0.0) << v;
        EXPECT_EQ(holds, v <= 2650.0) << v;
    }
}

TEST(SweepSearch, HoldingAtTheEndOrNowhere) {
    const cnc::sim::Bisection all = search_up_to(1e9, 0.0, 4800.0, 60.0);
    EXPECT_EQ(all.good(), 4800.0);
    EXPECT_FALSE(all.bad());
    EXPECT_EQ(all.tried().size(), 1u);
    const cnc::sim::Bisection none = search_up_to(-1.0, 100.0, 1000.0, 100.0);
    EXPECT_FALSE(none.any_held());
    EXPECT_EQ(none.good(), 100.0);  // `from`, taken to hold, never tried
    ASSERT_TRUE(none.bad());
    EXPECT_EQ(*none.bad(), 200.0);
}
