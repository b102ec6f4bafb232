// The ideal architecture on the square, the circle and the six-segment job with the ideal carriage (one microstep
// per step): its STEP edges against the half-step crossings of the planner's trajectory, found here by a plain scan
// and bisection of host::planner::plan's whole-program trajectory (not the architecture's search, which is
// metrics::step_crossings on the plan read as it runs), and its metrics against what a perfect quantiser allows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "architectures/ideal/ideal_settings.hpp"
#include "host/core/gcode.hpp"
#include "host/core/planner/planner.hpp"
#include "run/run.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {
namespace {

constexpr double kStepsPerMm = 160.0;  // the seed 000 machine the scenarios run on
constexpr double kStepUm = 1000.0 / kStepsPerMm;

RunOutcome run_ideal(const std::string& job, std::vector<std::string> sets = {}) {
    sets.emplace_back("mechanics.model=ideal");
    Scenario s = load_scenario(std::string(CNC_SOURCE_DIR) + "/scenarios/ideal/" + job + ".toml", sets);
    s.keep_run_input = true;  // every edge, for the comparison with the crossings
    return run_scenario(s);
}

host::planner::Trajectory planned(const std::string& job, const std::vector<std::string>& sets = {}) {
    const Scenario s = load_scenario(std::string(CNC_SOURCE_DIR) + "/scenarios/ideal/" + job + ".toml", sets);
    host::GcodeStream stream(s.job_path, s.interpreter, true);
    while (stream.next()) {
    }
    return host::planner::plan(stream.take(), s.settings<IdealSettings>().planner);
}

struct Crossing {
    TimePs t_ps;
    int direction;
};

// The instants the axis's planned position, in steps from the start, crosses n - 1/2 going up or n + 1/2 going
// down: a 10 us scan (the axis moves at most 16,000 steps/s on these jobs, 0.16 steps per scan interval, so one
// level per interval at most) and bisection to well under a picosecond.
std::vector<Crossing> crossings(const host::planner::Trajectory& traj, std::size_t axis) {
    const auto pos = [&](double t) {
        const geom::Vec2 p = traj.at(t).pos_mm;
        return (axis == 0 ? p.x_mm : p.y_mm) * kStepsPerMm;  // the jobs start at the origin
    };
    std::vector<Crossing> out;
    constexpr double kScanS = 10e-6;
    double t0 = 0.0;
    double p0 = pos(0.0);
    for (int k = 1; t0 < traj.duration_s(); ++k) {
        const double t1 = std::min(k * kScanS, traj.duration_s());
        const double p1 = pos(t1);
        const double lo_level = std::floor(std::min(p0, p1) + 0.5), hi_level = std::floor(std::max(p0, p1) + 0.5);
        if (lo_level != hi_level) {
            const double level = (p1 > p0 ? hi_level : hi_level) - 0.5;
            double a = t0, b = t1;
            for (int i = 0; i < 60; ++i) {
                const double m = 0.5 * (a + b);
                if ((pos(m) >= level) == (p1 > p0)) {
                    b = m;
                } else {
                    a = m;
                }
            }
            out.push_back({static_cast<TimePs>(std::ceil(b * 1e12 - 1e-3)), p1 > p0 ? 1 : -1});
        }
        t0 = t1;
        p0 = p1;
    }
    return out;
}

void expect_steps_at_crossings(const std::string& job) {
    const RunOutcome out = run_ideal(job);
    ASSERT_TRUE(out.ok) << out.failure;
    const host::planner::Trajectory traj = planned(job);
    for (std::size_t a = 0; a < 2; ++a) {
        const metrics::AxisTrace& axis = out.arch.input.axes[a];
        const std::vector<TimePs> rises = axis.step.rising();
        const std::vector<Crossing> expected = crossings(traj, a);
        ASSERT_FALSE(expected.empty()) << job << " axis " << a;
        for (std::size_t k = 0; k < std::min(rises.size(), expected.size()); ++k) {
            ASSERT_LE(std::llabs(rises[k] - expected[k].t_ps), 1'000'000)
                << job << " axis " << a << ": rise " << k << " at " << rises[k] << " ps, its crossing at "
                << expected[k].t_ps << " ps";
        }
        ASSERT_EQ(rises.size(), expected.size()) << job << " axis " << a;
        TimePs worst = 0;
        for (std::size_t k = 0; k < rises.size(); ++k) {
            worst = std::max<TimePs>(worst, std::llabs(rises[k] - expected[k].t_ps));
            const bool dir_high = axis.dir.level_at(rises[k]);
            ASSERT_EQ(dir_high == axis.dir_high_is_positive ? 1 : -1, expected[k].direction) << job << " step " << k;
        }
        EXPECT_LE(worst, 1) << job << " axis " << a << ": the farthest STEP rise from its crossing, ps";
    }
}

// The metrics of a perfect quantiser on the ideal carriage, the planner stopping at every corner (planner.mode =
// exact-stop: continuous blending leaves the programmed path by up to planner.path_tolerance_mm on purpose):
// - the tool ends on the programmed end, and each axis is never more than half a microstep from the trajectory, so
//   the tool is within sqrt(2)/2 of a microstep of it (following error) and of the path (contour error: a path at
//   angle a is left by |ex sin a - ey cos a| <= (|sin a| + |cos a|) / 2 microsteps; 4.42 um at 160 steps/mm);
// - every edge at its crossing (sync error) and every train of one rate exactly periodic (TIE, period jitter), to
//   the picosecond the edges are rounded to;
// - no dead time of its own: each gap between two moves is the time from the last half-step crossing before the
//   second move to the first one in it (a stop at a corner takes the deceleration through the last half step and
//   the acceleration through the first: 2 x sqrt(2 x 0.5 / 160 mm / 1000 mm/s^2) = 5 ms on the square).
void expect_quantiser_metrics(const std::string& job) {
    const std::vector<std::string> exact_stop = {"planner.mode=exact-stop"};
    const RunOutcome out = run_ideal(job, exact_stop);
    ASSERT_TRUE(out.ok) << out.failure;
    const metrics::RunMetrics& m = out.metrics;
    const double quantiser_um = std::sqrt(0.5) * kStepUm;
    ASSERT_TRUE(m.path.job_end_um.has_value());
    EXPECT_EQ(*m.path.job_end_um, 0.0) << job;
    ASSERT_TRUE(m.path.contour_max_um.has_value());
    EXPECT_LE(*m.path.contour_max_um, quantiser_um + 1e-6) << job;
    ASSERT_TRUE(m.path.following_max_um.has_value());
    EXPECT_LE(*m.path.following_max_um, quantiser_um + 1e-6) << job;
    ASSERT_TRUE(m.pulse.sync_max_abs_ns.has_value());
    EXPECT_LE(*m.pulse.sync_max_abs_ns, 0.001) << job;
    ASSERT_TRUE(m.pulse.tie_max_ns.has_value());
    EXPECT_LT(*m.pulse.tie_max_ns, 0.001) << job;
    ASSERT_TRUE(m.pulse.jitter_pp_max_ns.has_value());
    EXPECT_LE(*m.pulse.jitter_pp_max_ns, 0.001) << job;

    const host::planner::Trajectory traj = planned(job, exact_stop);
    std::vector<TimePs> all;
    for (std::size_t a = 0; a < 2; ++a) {
        for (const Crossing& c : crossings(traj, a)) all.push_back(c.t_ps);
    }
    std::sort(all.begin(), all.end());
    TimePs expected_ps = 0;
    const auto& windows = traj.move_windows();
    for (std::size_t k = 1; k < windows.size(); ++k) {
        const TimePs begin_ps = s_to_ps(windows[k].first);
        const auto after = std::lower_bound(all.begin(), all.end(), begin_ps);
        ASSERT_NE(after, all.begin());
        ASSERT_NE(after, all.end());
        expected_ps += *after - *std::prev(after);
    }
    ASSERT_EQ(m.timing.gap_count, windows.size() - 1) << job;
    ASSERT_TRUE(m.timing.dead_total_ms.has_value());
    EXPECT_NEAR(*m.timing.dead_total_ms, ps_to_s(expected_ps) * 1e3, 1e-9 * static_cast<double>(2 * windows.size()))
        << job;  // each crossing within 1 ps
}

TEST(IdealRun, SquareStepsAtTheTrajectorysHalfStepCrossings) {
    expect_steps_at_crossings("square_20mm");
}
TEST(IdealRun, CircleStepsAtTheTrajectorysHalfStepCrossings) {
    expect_steps_at_crossings("circle_r10");
}
TEST(IdealRun, SixSegmentStepsAtTheTrajectorysHalfStepCrossings) {
    expect_steps_at_crossings("six_segment");
}

TEST(IdealRun, SquareMetricsAreAPerfectQuantisers) {
    expect_quantiser_metrics("square_20mm");
}
TEST(IdealRun, CircleMetricsAreAPerfectQuantisers) {
    expect_quantiser_metrics("circle_r10");
}
TEST(IdealRun, SixSegmentMetricsAreAPerfectQuantisers) {
    expect_quantiser_metrics("six_segment");
}

}  // namespace
}  // namespace cnc::sim

namespace cnc::sim {
namespace {

// A simulated-time limit shorter than the job stops the run there: failed, its job end where it stopped.
TEST(IdealRun, AJobPastTheTimeLimitFails) {
    const RunOutcome out = run_ideal("square_20mm", {"scenario.max_sim_s=1"});
    EXPECT_FALSE(out.ok);
    EXPECT_EQ(out.failure.rfind("the job did not finish: stopped at ", 0), 0U) << out.failure;
    EXPECT_LE(out.arch.input.t_job_end_ps, 1'000 * kPsPerMs);
}

}  // namespace
}  // namespace cnc::sim
