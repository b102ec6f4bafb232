// Metric extensions for controllers with a trajectory planner (sim/metrics: RunInput::commanded and
// ::rate_segments): sync error against the commanded profile's step crossings, following error against the
// commanded position at the same time, pulse runs per commanded rate word.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "metrics/commanded.hpp"
#include "metrics/metrics.hpp"

using cnc::EdgeLog;
using cnc::kPsPerMs;
using cnc::kPsPerSec;
using cnc::kPsPerUs;
using cnc::TimePs;
using namespace cnc::metrics;

namespace {

constexpr double kStepsPerMm = 160.0;

// x(t) = v t for t in [0, 1 s] (held after), y = 0.
CommandedTrajectory ramp(double v_mm_per_s) {
    CommandedTrajectory c;
    c.t_begin_ps = 0;
    c.t_end_ps = kPsPerSec;
    c.state_at = [v_mm_per_s](TimePs t) {
        return CommandedState{{v_mm_per_s * cnc::ps_to_s(t), 0.0}, {v_mm_per_s, 0.0}};
    };
    return c;
}

// x(t) = A sin(2 pi f t) for t in [0, 1 s]: up, down through 0, and up again.
CommandedTrajectory sine(double a_mm, double f_hz) {
    CommandedTrajectory c;
    c.t_begin_ps = 0;
    c.t_end_ps = kPsPerSec;
    const double w = 2.0 * M_PI * f_hz;
    c.state_at = [a_mm, w](TimePs t) {
        const double s = cnc::ps_to_s(t);
        return CommandedState{{a_mm * std::sin(w * s), 0.0}, {a_mm * w * std::cos(w * s), 0.0}};
    };
    return c;
}

// STEP/DIR logs with a step at each time and the given direction (DIR high = +).
AxisTrace trace(const std::vector<TimePs>& rises, const std::vector<int>& signs, const std::string& name) {
    AxisTrace a;
    a.name = name;
    a.steps_per_mm = kStepsPerMm;
    a.step = EdgeLog{"step_" + name, false, {}};
    a.dir = EdgeLog{"dir_" + name, signs.empty() || signs.front() > 0, {}};
    bool dir = a.dir.initial;
    for (std::size_t k = 0; k < rises.size(); ++k) {
        const bool want = signs[k] > 0;
        if (want != dir) {
            a.dir.add(rises[k] - kPsPerUs, want);
            dir = want;
        }
        a.step.add(rises[k], true);
        a.step.add(rises[k] + 2 * kPsPerUs, false);
    }
    return a;
}

MoveSpec one_move(TimePs end_ps) {
    MoveSpec m;
    m.index = 1;
    m.path = cnc::geom::Segment::line({0, 0}, {1, 0});
    m.from_mm = {0, 0};
    m.to_mm = {1, 0};
    m.feed_mm_per_min = 60.0;
    m.steps = {160, 0};
    m.rate_steps_per_s = {160.0, 0.0};
    m.t_begin_ps = 0;
    m.t_end_ps = end_ps;
    return m;
}

}  // namespace

TEST(StepCrossings, RampCrossesEachHalfStepOnceUpToAPicosecond) {
    // 1 mm/s = 160 steps/s: level n - 1/2 at (n - 1/2) / 160 s.
    const StepCrossings c = step_crossings(ramp(1.0), 0, kStepsPerMm);
    EXPECT_TRUE(c.down.empty());
    ASSERT_EQ(c.up.size(), 160U);  // levels 0.5 .. 159.5; 160.5 is past the end (160 at 1 s)
    EXPECT_EQ(c.up.begin()->first, 1);
    EXPECT_EQ(c.up.rbegin()->first, 160);
    for (const auto& [n, times] : c.up) {
        ASSERT_EQ(times.size(), 1U);
        const double exact_ps = (static_cast<double>(n) - 0.5) / 160.0 * 1e12;
        EXPECT_LE(std::fabs(static_cast<double>(times[0]) - exact_ps), 1.0) << n;
    }
}

// A scan point one ulp under a half-step level: the planner's diagonal at 1000 mm/s^2 puts the square's first X step
// there (0.0031249999999999997 mm at 2.5 ms, 0.49999999999999994 steps), and 0.49999999999999994 + 0.5 rounds to
// 1.0. Here x(t) = that position + 1 mm/s (t - 2.5 ms), both ways: the level is crossed in the interval that starts
// at the point, and found there.
TEST(StepCrossings, ALevelOneUlpAboveAScanPointIsNotSkipped) {
    const double under_half_step = std::nextafter(0.5, 0.0);
    for (const double sign : {1.0, -1.0}) {
        CommandedTrajectory c;
        c.t_begin_ps = 0;
        c.t_end_ps = 4 * kPsPerMs;
        c.scan_step_ps = 100 * kPsPerUs;
        c.state_at = [sign, under_half_step](TimePs t) {
            const double x = under_half_step / kStepsPerMm + (cnc::ps_to_s(t) - 0.0025);
            return CommandedState{{sign * x, 0.0}, {sign * 1.0, 0.0}};
        };
        ASSERT_EQ(sign * c.state_at(2'500 * kPsPerUs).pos_mm.x_mm * kStepsPerMm, under_half_step);
        const StepCrossings x = step_crossings(c, 0, kStepsPerMm);
        const std::int64_t count = sign > 0 ? 1 : -1;  // the step through +-0.5
        const auto& levels = sign > 0 ? x.up : x.down;
        ASSERT_EQ(levels.count(count), 1U) << sign;
        // 1 ulp of position at 160 steps/s is far under a picosecond: the first ps past 2.5 ms.
        EXPECT_EQ(levels.at(count).front(), 2'500 * kPsPerUs + 1) << sign;
    }
}

TEST(StepCrossings, ATurningPointInsideAScanStepSplitsTheInterval) {
    // A = 1 mm (160 steps) at 1 Hz: up to 160 at 0.25 s, down to -160 at 0.75 s, back to 0 at 1 s. A 300 ms scan
    // step puts both turning points inside intervals.
    CommandedTrajectory c = sine(1.0, 1.0);
    c.scan_step_ps = 300 * kPsPerMs;
    const StepCrossings x = step_crossings(c, 0, kStepsPerMm);
    // up: levels 0.5..159.5 twice (rising from 0 and from -160 back to 0 only up to -0.5: counts -159..0)
    ASSERT_EQ(x.up.count(1), 1U);
    EXPECT_EQ(x.up.at(1).size(), 1U);
    EXPECT_EQ(x.up.at(0).size(), 1U);  // -0.5 rising, near the end
    EXPECT_EQ(x.up.at(-159).size(), 1U);
    EXPECT_EQ(x.up.count(-160), 0U);        // the minimum -160 is not crossed through -160.5
    EXPECT_EQ(x.down.at(0).size(), 1U);     // 0.5 falling
    EXPECT_EQ(x.down.at(-160).size(), 1U);  // -159.5 falling
    EXPECT_EQ(x.up.at(160).size(), 1U);     // 159.5 rising just before the top
    // 159.5 = 160 sin(2 pi t): t = asin(159.5/160) / (2 pi)
    const double t_up = std::asin(159.5 / 160.0) / (2 * M_PI) * 1e12;
    EXPECT_LE(std::fabs(static_cast<double>(x.up.at(160)[0]) - t_up), 1.0);
    EXPECT_LE(std::fabs(static_cast<double>(x.down.at(159)[0]) - (0.5e12 - t_up)), 1.0);
}

TEST(CommandedSync, EdgesOneMillisecondLateReadOneMillisecond) {
    std::vector<TimePs> rises;
    for (int n = 1; n <= 160; ++n) {
        rises.push_back(static_cast<TimePs>(std::llround((n - 0.5) / 160.0 * 1e12)) + kPsPerMs);
    }
    RunInput in;
    in.axes = {trace(rises, std::vector<int>(rises.size(), 1), "x")};
    in.moves = {one_move(kPsPerSec)};
    in.commanded = ramp(1.0);
    const RunMetrics m = compute_metrics(in);
    ASSERT_TRUE(m.axes[0].sync_max_abs_ns.has_value());
    EXPECT_NEAR(*m.axes[0].sync_max_abs_ns, 1e6, 0.002);
    EXPECT_EQ(m.axes[0].sync_unmatched_edges, 0U);
    EXPECT_NEAR(*m.moves[0].sync_max_abs_ns[0], 1e6, 0.002);
}

TEST(CommandedSync, AStepTheCommandNeverMakesNearbyIsUnmatched) {
    // Steps 1..10 on time, then a step to 11 long after the command stopped at 10 (ramp held past 1/16 s).
    CommandedTrajectory c = ramp(1.0);
    c.t_end_ps = static_cast<TimePs>(10.0 / 160.0 * 1e12);
    std::vector<TimePs> rises;
    for (int n = 1; n <= 10; ++n) rises.push_back(static_cast<TimePs>(std::llround((n - 0.5) / 160.0 * 1e12)));
    rises.push_back(500 * kPsPerMs);
    RunInput in;
    in.axes = {trace(rises, std::vector<int>(rises.size(), 1), "x")};
    in.moves = {one_move(kPsPerSec)};
    in.commanded = c;
    const RunMetrics m = compute_metrics(in);
    EXPECT_EQ(m.axes[0].sync_unmatched_edges, 1U);
    EXPECT_LE(*m.axes[0].sync_max_abs_ns, 0.001);
}

TEST(CommandedSync, ReversalsMatchTheDownwardCrossings) {
    // The sine's steps, each exactly at its crossing, with DIR: all sync errors 0 (to the ps), none unmatched.
    const CommandedTrajectory c = sine(0.1, 2.0);  // 16 steps, 2 Hz
    const StepCrossings x = step_crossings(c, 0, kStepsPerMm);
    std::vector<std::pair<TimePs, int>> events;
    for (const auto& [n, times] : x.up)
        for (TimePs t : times) events.push_back({t, +1});
    for (const auto& [n, times] : x.down)
        for (TimePs t : times) events.push_back({t, -1});
    std::sort(events.begin(), events.end());
    std::vector<TimePs> rises;
    std::vector<int> signs;
    for (const auto& [t, s] : events) {
        rises.push_back(t);
        signs.push_back(s);
    }
    ASSERT_EQ(rises.size(), 4U * 2U * 16U);  // two periods, 4 x 16 half-levels each
    RunInput in;
    in.axes = {trace(rises, signs, "x")};
    in.moves = {one_move(kPsPerSec)};
    in.commanded = c;
    const RunMetrics m = compute_metrics(in);
    EXPECT_EQ(m.axes[0].sync_unmatched_edges, 0U);
    EXPECT_LE(*m.axes[0].sync_max_abs_ns, 0.001);
    EXPECT_EQ(m.axes[0].net_steps, 0);
}

TEST(CommandedFollowing, DistanceToTheCommandBeforeAndAfterEachStep) {
    // The command moves 1 mm/s; the tool jumps one step (6.25 um) at t = 10 ms and 20 ms. At 10 ms the command is at
    // 10 um: 10 um before the step (tool at 0), 3.75 um after. At 20 ms: 20 - 6.25 = 13.75 before, 7.5 after.
    RunInput in;
    in.axes = {trace({10 * kPsPerMs, 20 * kPsPerMs}, {1, 1}, "x")};
    in.moves = {one_move(kPsPerSec)};
    in.commanded = ramp(1.0);
    in.tool = {{0, {0.0, 0.0}}, {10 * kPsPerMs, {1 / 160.0, 0.0}}, {20 * kPsPerMs, {2 / 160.0, 0.0}}};
    const RunMetrics m = compute_metrics(in);
    EXPECT_NEAR(*m.path.following_max_um, 13.75, 1e-9);
    EXPECT_NEAR(*m.path.following_rms_um, std::sqrt((0.0 + 10.0 * 10.0 + 13.75 * 13.75) / 3.0), 1e-9);
}

TEST(RateSegmentRuns, OneRunPerCommandedWordWithItsRate) {
    // 100 us period for 1 ms, then 125 us; the segments say 10,010 and 7,990 steps/s were asked for.
    std::vector<TimePs> rises;
    for (int k = 0; k < 10; ++k) rises.push_back(k * 100 * kPsPerUs);
    for (int k = 0; k < 8; ++k) rises.push_back(kPsPerMs + k * 125 * kPsPerUs);
    RunInput in;
    in.axes = {trace(rises, std::vector<int>(rises.size(), 1), "x")};
    in.moves = {one_move(kPsPerSec)};
    in.rate_segments = {{{0, 10'010.0}, {kPsPerMs, 7'990.0}, {2 * kPsPerMs, 0.0}}};
    const RunMetrics m = compute_metrics(in);
    EXPECT_TRUE(m.runs_per_rate_segment);
    ASSERT_EQ(m.axes[0].runs.size(), 2U);
    const PulseRun& a = m.axes[0].runs[0];
    const PulseRun& b = m.axes[0].runs[1];
    EXPECT_EQ(a.edges(), 10U);
    EXPECT_EQ(b.edges(), 8U);
    EXPECT_EQ(a.move, 0U);
    EXPECT_NEAR(*a.rate_error_pct, (10'000.0 - 10'010.0) / 10'010.0 * 100.0, 1e-9);
    EXPECT_NEAR(*b.rate_error_pct, (8'000.0 - 7'990.0) / 7'990.0 * 100.0, 1e-9);
    EXPECT_NEAR(a.tie->max_abs_ns, 0.0, 1e-6);
    EXPECT_NEAR(m.axes[0].pulse.jitter_pp_max_ns.value(), 0.0, 1e-9);  // within each word: one period
}

TEST(RateSegmentRuns, WithoutSegmentsRunsStayPerMove) {
    RunInput in;
    in.axes = {trace({0, 100 * kPsPerUs, 200 * kPsPerUs}, {1, 1, 1}, "x")};
    in.moves = {one_move(kPsPerSec)};
    const RunMetrics m = compute_metrics(in);
    EXPECT_FALSE(m.runs_per_rate_segment);
    ASSERT_EQ(m.axes[0].runs.size(), 1U);
    EXPECT_NEAR(*m.axes[0].runs[0].rate_commanded_steps_per_s, 160.0, 1e-12);
    EXPECT_FALSE(m.axes[0].sync_unmatched_edges.has_value());
}
