#include <gtest/gtest.h>

#include <cmath>

#include "metrics/metrics.hpp"
#include "metrics/timing/job_gaps.hpp"
#include "metrics_test_util.hpp"

namespace cnc::metrics {
namespace {

using test::grid;
using test::kFpgaClockPs;

TEST(MetricsMoveTiming, FeedErrorOfTheSeedWorkedExample) {
    // Seed 000: (0,0) -> (10,5) at F1000 on 160 steps/mm: X 1600 steps every 20,973 clocks, Y 800 every
    // 41,946 clocks. Motion time = 1600 * 20,973 * 20 ns = 0.671136 s; 11.1803 mm in it = 999.5 mm/min.
    const TimePs t0 = 3 * kPsPerMs;
    RunInput in;
    in.axes.push_back(test::axis(grid(t0, 20'973 * kFpgaClockPs, 1600), "x"));
    in.axes.push_back(test::axis(grid(t0, 41'946 * kFpgaClockPs, 800), "y"));
    MoveSpec move = test::line_move(0, {0, 0}, {10, 5}, 1000.0, 0, 700 * kPsPerMs);
    move.steps = {1600, 800};
    in.moves.push_back(move);
    const RunMetrics m = compute_metrics(in);
    const MoveTiming& t = m.moves[0].timing;
    EXPECT_NEAR(*t.motion_time_s, 0.671136, 1e-12);
    const double achieved = std::sqrt(125.0) / 0.671136 * 60.0;
    EXPECT_NEAR(*t.achieved_feed_mm_per_min, achieved, 1e-9);
    EXPECT_NEAR(*t.achieved_feed_mm_per_min, 999.5, 0.05);
    EXPECT_NEAR(*t.feed_error_pct, (achieved - 1000.0) / 10.0, 1e-9);
    EXPECT_NEAR(*t.feed_error_pct, -0.05, 0.005);
    EXPECT_EQ(m.timing.feed_moves, 1U);
    EXPECT_DOUBLE_EQ(*m.timing.feed_error_max_abs_pct, -*t.feed_error_pct);
    EXPECT_DOUBLE_EQ(*m.timing.feed_error_mean_pct, *t.feed_error_pct);
    EXPECT_NEAR(*m.timing.motion_time_s, 0.671136, 1e-12);
    EXPECT_EQ(m.moves[0].steps_emitted, (std::vector<std::int64_t>{1600, 800}));
}

TEST(MetricsMoveTiming, SingleStepAxisUsesItsCommandedRateAndRapidsHaveNoFeedError) {
    RunInput in;
    in.axes.push_back(test::axis({kPsPerMs}, "x"));
    MoveSpec move = test::line_move(0, {0, 0}, {1.0 / 160, 0}, 600.0, 0, 2 * kPsPerMs);
    move.rate_steps_per_s = {1'600.0, 0.0};
    move.rapid = true;
    in.moves.push_back(move);
    const RunMetrics m = compute_metrics(in);
    EXPECT_NEAR(*m.moves[0].timing.motion_time_s, 1.0 / 1600.0, 1e-15);
    EXPECT_FALSE(m.moves[0].timing.feed_error_pct.has_value());
    EXPECT_EQ(m.timing.feed_moves, 0U);
}

// Two pieces of one programmed move (programmed = 0, as an arc's chords) and a move of its own: timing is defined
// on the programmed move, the pause between its pieces inside its motion time, and a dead time inside the move.
TEST(MetricsMoveTiming, PiecesOfOneProgrammedMoveAreTimedAsOneMove) {
    // Piece 0: X steps at 1..10 ms; piece 1: at 12..21 ms (a 2 ms pause after 10 ms); move 2: 24..28 ms.
    RunInput in;
    std::vector<TimePs> x = grid(kPsPerMs, kPsPerMs, 10);
    for (const TimePs t0 : {12 * kPsPerMs, 24 * kPsPerMs}) {
        const std::vector<TimePs> more = grid(t0, kPsPerMs, t0 == 12 * kPsPerMs ? 10 : 5);
        x.insert(x.end(), more.begin(), more.end());
    }
    in.axes.push_back(test::axis(x, "x"));
    const double step = 1.0 / 160;
    MoveSpec a = test::line_move(0, {0, 0}, {10 * step, 0}, 375.0, 0, 11 * kPsPerMs);
    MoveSpec b = test::line_move(1, {10 * step, 0}, {20 * step, 0}, 375.0, 11 * kPsPerMs, 23 * kPsPerMs);
    a.path = b.path = geom::Segment::line({0, 0}, {20 * step, 0});
    a.programmed = b.programmed = 0;
    MoveSpec c = test::line_move(2, {20 * step, 0}, {25 * step, 0}, 375.0, 23 * kPsPerMs, 30 * kPsPerMs);
    c.programmed = 1;
    in.moves = {a, b, c};
    in.t_job_end_ps = 30 * kPsPerMs;
    const RunMetrics m = compute_metrics(in);
    ASSERT_EQ(m.pieces.size(), 3U);
    ASSERT_EQ(m.moves.size(), 2U);
    EXPECT_EQ(m.moves[0].index, 1);
    EXPECT_EQ(m.moves[0].pieces, 2U);
    EXPECT_EQ(m.moves[0].steps_emitted, std::vector<std::int64_t>{20});
    // Move 1: first edge 1 ms, last 21 ms plus its 1 ms period: 21 ms for 20 steps of 1/160 mm (0.125 mm): the
    // 375 mm/min of its pieces, slowed by the pause to 0.125 mm / 21 ms = 357.14 mm/min, -1/21 = -4.76 %.
    EXPECT_NEAR(*m.moves[0].timing.motion_time_s, 0.021, 1e-12);
    EXPECT_NEAR(*m.moves[0].timing.feed_error_pct, -100.0 / 21.0, 1e-9);
    // Move 2: 5 periods at F: no error. One gap, between the programmed moves: 24 - 21 = 3 ms.
    EXPECT_NEAR(*m.moves[1].timing.feed_error_pct, 0.0, 1e-9);
    const std::vector<DeadGap> gaps = dead_gaps(m.moves);
    ASSERT_EQ(gaps.size(), 1U);
    EXPECT_EQ(gaps[0].dead_ps, 3 * kPsPerMs);
    EXPECT_NEAR(*m.timing.motion_time_s, 0.026, 1e-12);
    // Inside move 1: piece 0's last edge at 10 ms to piece 1's first at 12 ms, 2 ms; job: 3 + 2 = 5 ms.
    EXPECT_EQ(m.moves[0].timing.inside_gaps, 1U);
    EXPECT_EQ(m.moves[0].timing.dead_inside_ps, 2 * kPsPerMs);
    EXPECT_EQ(m.moves[1].timing.inside_gaps, 0U);
    EXPECT_EQ(m.timing.gap_count, 1U);
    EXPECT_EQ(m.timing.inside_gap_count, 1U);
    EXPECT_DOUBLE_EQ(*m.timing.dead_inside_total_ms, 2.0);
    EXPECT_DOUBLE_EQ(*m.timing.dead_inside_mean_ms, 2.0);
    EXPECT_DOUBLE_EQ(*m.timing.dead_inside_max_ms, 2.0);
    EXPECT_DOUBLE_EQ(*m.timing.dead_all_total_ms, 5.0);
    // Every gap in job order, with its pieces: inside move 0 (pieces 0 -> 1), then between moves 0 and 1 (1 -> 2).
    const std::vector<JobGap> all = job_gaps(m.moves, m.pieces);
    ASSERT_EQ(all.size(), 2U);
    EXPECT_TRUE(all[0].inside());
    EXPECT_EQ(all[0].after_move, 0U);
    EXPECT_EQ(all[0].after_piece, 0U);
    EXPECT_EQ(all[0].before_piece, 1U);
    EXPECT_EQ(all[0].dead_ps, 2 * kPsPerMs);
    EXPECT_FALSE(all[1].inside());
    EXPECT_EQ(all[1].before_move, 1U);
    EXPECT_EQ(all[1].after_piece, 1U);
    EXPECT_EQ(all[1].before_piece, 2U);
    EXPECT_EQ(all[1].dead_ps, 3 * kPsPerMs);
    // Without the pieces (a streamed run without --detail) there is no list.
    EXPECT_TRUE(job_gaps(m.moves, {}).empty());
}

TEST(MetricsMoveTiming, DeadTimeBetweenMovesAndJobTotals) {
    // Move 0 steps at 1..10 ms, move 1 (no steps) in between, move 2 from 12.5 ms: one gap of 2.5 ms.
    RunInput in;
    std::vector<TimePs> x = grid(kPsPerMs, kPsPerMs, 10);
    const std::vector<TimePs> x2 = grid(12'500 * kPsPerUs, kPsPerMs, 5);
    x.insert(x.end(), x2.begin(), x2.end());
    in.axes.push_back(test::axis(x, "x"));
    in.moves.push_back(test::line_move(0, {0, 0}, {10.0 / 160, 0}, 375.0, 0, 10 * kPsPerMs));
    in.moves.push_back(test::line_move(1, {10.0 / 160, 0}, {10.0 / 160, 0}, 375.0, 11 * kPsPerMs, 11 * kPsPerMs));
    in.moves.push_back(test::line_move(2, {10.0 / 160, 0}, {15.0 / 160, 0}, 375.0, 12 * kPsPerMs, 20 * kPsPerMs));
    in.t_job_start_ps = 0;
    in.t_job_end_ps = 20 * kPsPerMs;
    const RunMetrics m = compute_metrics(in);
    const std::vector<DeadGap> gaps = dead_gaps(m.moves);
    ASSERT_EQ(gaps.size(), 1U);
    EXPECT_EQ(gaps[0].after_move, 0U);
    EXPECT_EQ(gaps[0].before_move, 2U);
    EXPECT_EQ(gaps[0].dead_ps, 2'500 * kPsPerUs);
    EXPECT_DOUBLE_EQ(*m.timing.dead_total_ms, 2.5);
    EXPECT_DOUBLE_EQ(*m.timing.dead_mean_ms, 2.5);
    EXPECT_DOUBLE_EQ(*m.timing.dead_max_ms, 2.5);
    // Each move steps in one piece: nothing inside, the total is the gap between.
    EXPECT_EQ(m.timing.inside_gap_count, 0U);
    EXPECT_DOUBLE_EQ(*m.timing.dead_inside_total_ms, 0.0);
    EXPECT_FALSE(m.timing.dead_inside_mean_ms.has_value());
    EXPECT_DOUBLE_EQ(*m.timing.dead_all_total_ms, 2.5);
    EXPECT_DOUBLE_EQ(m.timing.job_time_s, 0.020);
    EXPECT_DOUBLE_EQ(*m.timing.lead_in_ms, 1.0);
    EXPECT_DOUBLE_EQ(*m.timing.tail_ms, 3.5);  // last step at 16.5 ms
    // Motion: 10 and 5 periods of 1 ms; the step-less move adds nothing.
    EXPECT_NEAR(*m.timing.motion_time_s, 0.015, 1e-12);
    EXPECT_FALSE(m.moves[1].timing.motion_time_s.has_value());
    // Both stepping moves run at exactly their F (1/160 mm per ms = 375 mm/min).
    EXPECT_NEAR(*m.timing.feed_error_mean_abs_pct, 0.0, 1e-9);
}

}  // namespace
}  // namespace cnc::metrics
