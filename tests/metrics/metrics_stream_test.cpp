#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "metrics/metrics.hpp"
#include "metrics/report/report.hpp"
#include "metrics/streaming/metrics_stream.hpp"
#include "metrics_test_util.hpp"

namespace cnc::metrics {
namespace {

using test::kMicrostepMm;

constexpr TimePs kUs = kPsPerUs;

struct PieceDef {
    int programmed;
    bool rapid;
    int steps_x, steps_y;  // signed microsteps
};

// A run with what every family has to carry across a window cut: edges before the first piece, a programmed move
// in two pieces, a rapid, a piece without steps, DIR changes, one short STEP pulse (a driver violation), the laser
// switched on while the tool stands still (dwell) and during the rapid. Each piece steps at 100 us per step on its
// longer axis from 50 us after it begins; the tool is sampled at every rise and at every piece's start.
RunInput synthetic_run() {
    const std::vector<PieceDef> defs{{0, false, 12, 0}, {1, false, 8, 4},   {1, false, 8, 4}, {2, true, -10, 6},
                                     {3, false, 0, 0},  {4, false, -6, -9}, {5, false, 5, 0}};
    RunInput in;
    in.axes = {test::axis({}, "x"), test::axis({}, "y")};
    for (AxisTrace& a : in.axes) {
        a.step.edges.clear();
        a.steps_per_mm = 1.0 / kMicrostepMm;
    }
    in.laser = EdgeLog{"laser", false, {}};
    std::vector<ToolSample> tool;
    std::int64_t pos[2] = {0, 0};
    const auto position = [&] { return geom::Vec2{pos[0] * kMicrostepMm, pos[1] * kMicrostepMm}; };
    const auto rise = [&](std::size_t a, TimePs t, TimePs high_ps) {
        in.axes[a].step.add(t, true);
        in.axes[a].step.add(t + high_ps, false);
    };
    // Two steps before the first piece: unattributed.
    rise(0, 100 * kUs, 2 * kUs);
    rise(0, 200 * kUs, 2 * kUs);
    pos[0] = 2;
    tool.push_back({100 * kUs, {kMicrostepMm, 0.0}});
    tool.push_back({200 * kUs, position()});
    bool dir[2] = {true, true};
    TimePs t = 1'000 * kUs;
    for (std::size_t p = 0; p < defs.size(); ++p) {
        const PieceDef& d = defs[p];
        const int steps[2] = {d.steps_x, d.steps_y};
        const int longest = std::max(std::abs(d.steps_x), std::abs(d.steps_y));
        const TimePs duration = longest * 100 * kUs;
        MoveSpec m = test::line_move(static_cast<int>(p), position(), {}, 0.0, t, 0);
        m.programmed = d.programmed;
        m.rapid = d.rapid;
        tool.push_back({t, position()});
        if (p == 0) in.laser->add(t - 20 * kUs, true);
        if (p == 3) in.laser->add(t + 300 * kUs, true);
        const TimePs t0 = t + 50 * kUs;
        std::vector<std::pair<TimePs, std::size_t>> rises;
        for (std::size_t a = 0; a < 2; ++a) {
            if (steps[a] == 0) continue;
            const bool positive = steps[a] > 0;
            if (positive != dir[a]) {
                in.axes[a].dir.add(t0 - 10 * kUs, positive);
                dir[a] = positive;
            }
            const TimePs period = duration / std::abs(steps[a]);
            for (int k = 0; k < std::abs(steps[a]); ++k) rises.emplace_back(t0 + k * period, a);
        }
        std::sort(rises.begin(), rises.end());
        for (std::size_t k = 0; k < rises.size(); ++k) {
            const auto [tr, a] = rises[k];
            rise(a, tr, p == 5 && k == 0 ? 1 * kUs : 2 * kUs);
            pos[a] += steps[a] > 0 ? 1 : -1;
            tool.push_back({tr, position()});
        }
        m.to_mm = position();
        m.path = geom::Segment::line(m.from_mm, m.to_mm);
        for (std::size_t a = 0; a < 2; ++a) {
            m.steps.push_back(steps[a]);
            m.rate_steps_per_s.push_back(duration > 0 ? std::abs(steps[a]) / ps_to_s(duration) : 0.0);
        }
        // 2 % below the speed of the steps, so that the feed error is not 0.
        m.feed_mm_per_min = duration > 0 ? geom::distance(m.from_mm, m.to_mm) / ps_to_s(duration) * 60.0 * 0.98 : 600;
        m.t_end_ps = t0 + duration + 30 * kUs;
        if (p == 2 || p == 5) in.laser->add(p == 2 ? m.t_end_ps : t0 + duration / 2, false);
        t = m.t_end_ps + 200 * kUs;
        in.moves.push_back(m);
    }
    // A programmed move of two pieces takes the path of the whole line.
    in.moves[1].path = in.moves[2].path = geom::Segment::line(in.moves[1].from_mm, in.moves[2].to_mm);
    in.tool = std::move(tool);
    in.t_job_start_ps = 0;
    in.t_job_end_ps = t + 300 * kUs;
    return in;
}

template <typename T, typename Time>
void append_window(std::vector<T>& to, const std::vector<T>& from, TimePs lo, TimePs hi, Time time_of) {
    for (const T& x : from) {
        if (time_of(x) >= lo && time_of(x) < hi) to.push_back(x);
    }
}

// `detail`: the stream keeps the per-piece records and pulse runs; without, the default report is still the batch one.
class MetricsStreamWindows : public ::testing::TestWithParam<bool> {};

// Hands `whole` to a stream window by window (cut at `cuts`, the last after the job's end) as a run would: what
// happened before each cut, the pieces begun before it, the rate segments from before it and the commanded
// trajectory known up to it. Returns the streamed metrics; `fewest_kept`: the fewest x STEP edges the stream held
// after a cut between the rapid's start and the job's end.
RunMetrics stream_in_windows(const RunInput& whole, bool detail, const std::vector<TimePs>& cuts,
                             std::size_t& pieces_measured, std::size_t& fewest_kept) {
    RunInput shape = whole;
    for (AxisTrace& a : shape.axes) a.step.edges.clear(), a.dir.edges.clear();
    shape.laser->edges.clear();
    shape.tool.clear();
    shape.moves.clear();
    for (std::vector<RateSegment>& segments : shape.rate_segments) segments.clear();
    if (shape.commanded) shape.commanded->t_end_ps = shape.commanded->t_begin_ps;
    pieces_measured = 0;
    MetricsStream stream(shape, detail, [&pieces_measured](const MoveMetrics&) { ++pieces_measured; });
    TimePs lo = 0;
    std::size_t pieces_given = 0;
    fewest_kept = whole.axes[0].step.edges.size();
    for (const TimePs hi : cuts) {
        RunInput& p = stream.pending();
        const auto edge_time = [](const Edge& e) { return e.t_ps; };
        for (std::size_t a = 0; a < whole.axes.size(); ++a) {
            append_window(p.axes[a].step.edges, whole.axes[a].step.edges, lo, hi, edge_time);
            append_window(p.axes[a].dir.edges, whole.axes[a].dir.edges, lo, hi, edge_time);
        }
        for (std::size_t a = 0; a < whole.rate_segments.size(); ++a) {
            append_window(p.rate_segments[a], whole.rate_segments[a], lo, hi,
                          [](const RateSegment& r) { return r.t_ps; });
        }
        if (p.commanded) p.commanded->t_end_ps = std::min(hi, whole.commanded->t_end_ps);
        append_window(p.laser->edges, whole.laser->edges, lo, hi, edge_time);
        append_window(p.tool, whole.tool, lo, hi, [](const ToolSample& s) { return s.t_ps; });
        for (; pieces_given < whole.moves.size() && whole.moves[pieces_given].t_begin_ps < hi; ++pieces_given) {
            p.moves.push_back(whole.moves[pieces_given]);
        }
        p.t_job_end_ps = hi;
        stream.fold(hi);
        if (hi > whole.moves[3].t_begin_ps && hi < whole.t_job_end_ps) {
            fewest_kept = std::min(fewest_kept, stream.pending().axes[0].step.edges.size());
        }
        lo = hi;
    }
    return stream.finish(whole.t_job_end_ps);
}

TEST_P(MetricsStreamWindows, WindowByWindowEqualsTheWholeRun) {
    const bool detail = GetParam();
    const RunInput whole = synthetic_run();
    const RunMetrics batch = compute_metrics(whole);
    ASSERT_EQ(batch.moves.size(), 6U);  // pieces 1 and 2 are one programmed move
    ASSERT_GT(batch.pulse.driver_violations, 0U);
    ASSERT_GT(*batch.laser->dwell_ms, 0.0);
    ASSERT_GT(*batch.laser->on_in_rapid_ms, 0.0);

    // Cuts every 370 us, one at a rise of the two-piece move (2,350 us: y's first) and one inside that pulse.
    std::vector<TimePs> cuts;
    for (TimePs c = 370 * kUs; c < whole.t_job_end_ps; c += 370 * kUs) cuts.push_back(c);
    const TimePs tied_rise = whole.moves[1].t_begin_ps + 50 * kUs;
    cuts.push_back(tied_rise);
    cuts.push_back(tied_rise + 1 * kUs);
    std::sort(cuts.begin(), cuts.end());
    cuts.push_back(whole.t_job_end_ps + 1);

    std::size_t pieces_measured = 0;
    std::size_t fewest_kept = 0;
    const RunMetrics streamed = stream_in_windows(whole, detail, cuts, pieces_measured, fewest_kept);
    // The measured moves' edges were dropped on the way: the x STEP log never held all of the run after the rapid.
    EXPECT_LT(fewest_kept, whole.axes[0].step.edges.size() / 2);
    EXPECT_EQ(to_json(streamed, detail).dump(1), to_json(batch, detail).dump(1));
    EXPECT_EQ(pieces_measured, whole.moves.size());
    EXPECT_EQ(streamed.pieces.size(), detail ? whole.moves.size() : 0U);
    EXPECT_EQ(streamed.axes[0].runs.empty(), !detail);
}

// A planner's run (spi-fpga): the commanded trajectory, known only up to each cut, moves each piece's commanded
// end points linearly over its steps (sync error and cruise feed against it, the step counts carried across cuts),
// and the runs follow rate segments (one per piece and axis from its first step, a change in the middle of piece 0
// whose run a cut splits in time, a stop at each piece's end, one before the unattributed steps).
TEST_P(MetricsStreamWindows, PlannerRunWindowByWindowEqualsTheWholeRun) {
    const bool detail = GetParam();
    RunInput whole = synthetic_run();
    struct Leg {
        TimePs t0, t1;
        geom::Vec2 from, to;
    };
    std::vector<Leg> legs;
    whole.rate_segments.assign(2, {{50 * kUs, 10'000.0}});
    for (const MoveSpec& m : whole.moves) {
        // synthetic_run: steps from 50 us after the piece's begin to 30 us before its end.
        const Leg leg{m.t_begin_ps + 50 * kUs, m.t_end_ps - 30 * kUs, m.from_mm, m.to_mm};
        legs.push_back(leg);
        for (std::size_t a = 0; a < 2; ++a) {
            if (m.steps[a] == 0) continue;
            if (&m == &whole.moves.front()) {
                whole.rate_segments[a].push_back({leg.t0, m.rate_steps_per_s[a]});
                whole.rate_segments[a].push_back({leg.t0 + (leg.t1 - leg.t0) / 2, m.rate_steps_per_s[a] * 1.01});
            } else {
                whole.rate_segments[a].push_back({leg.t0, m.rate_steps_per_s[a]});
            }
            whole.rate_segments[a].push_back({m.t_end_ps, 0.0});
        }
    }
    CommandedTrajectory c;
    c.t_begin_ps = 0;
    c.t_end_ps = whole.t_job_end_ps;
    c.scan_step_ps = 20 * kUs;
    c.sync_window_ps = 150 * kUs;  // 1.5 x the step period: an edge matches its own crossing only
    c.state_at = [legs](TimePs t) {
        geom::Vec2 at{};
        for (const Leg& leg : legs) {
            if (t < leg.t0) return CommandedState{at, {}};
            if (t <= leg.t1) {
                const double f = static_cast<double>(t - leg.t0) / static_cast<double>(leg.t1 - leg.t0);
                const double s = ps_to_s(leg.t1 - leg.t0);
                return CommandedState{leg.from + (leg.to - leg.from) * f, (leg.to - leg.from) * (1.0 / s)};
            }
            at = leg.to;
        }
        return CommandedState{at, {}};
    };
    whole.commanded = c;
    const RunMetrics batch = compute_metrics(whole);
    ASSERT_TRUE(batch.runs_per_rate_segment);
    ASSERT_GT(*batch.axes[0].sync_unmatched_edges, 0U);  // the unattributed steps: no commanded motion then
    ASSERT_TRUE(batch.pulse.sync_max_abs_ns);
    ASSERT_GT(batch.timing.feed_moves, 0U);

    std::vector<TimePs> cuts;
    for (TimePs t = 370 * kUs; t < whole.t_job_end_ps; t += 370 * kUs) cuts.push_back(t);
    cuts.push_back(whole.t_job_end_ps + 1);
    std::size_t pieces_measured = 0;
    std::size_t fewest_kept = 0;
    const RunMetrics streamed = stream_in_windows(whole, detail, cuts, pieces_measured, fewest_kept);
    EXPECT_LT(fewest_kept, whole.axes[0].step.edges.size() / 2);
    EXPECT_EQ(to_json(streamed, detail).dump(1), to_json(batch, detail).dump(1));
    EXPECT_EQ(pieces_measured, whole.moves.size());
}

INSTANTIATE_TEST_SUITE_P(DetailOrNot, MetricsStreamWindows, ::testing::Bool());

}  // namespace
}  // namespace cnc::metrics
