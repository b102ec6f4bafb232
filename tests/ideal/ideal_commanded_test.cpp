// The ideal controller's sync error is a function of its plan alone. Its metrics read the commanded trajectory while
// the run's trajectory clock is knotted at every slice end, and a slice's length follows the wall time
// (sim/run/simulate.cpp: doubled below 50 ms of wall time, halved above 200 ms), so a loaded machine knots the clock
// elsewhere. Here the circle's STEP edges are made as the ideal makes them (IdealEdges, without SystemC) and measured
// against the commanded trajectory with the clock knotted at the slice ends of two schedules: every edge's sync
// error is the same to the picosecond in both, and 0, as each edge is at its own half-step crossing.
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "architectures/ideal/ideal_edges.hpp"
#include "architectures/ideal/ideal_settings.hpp"
#include "architectures/planner/planned_job.hpp"
#include "architectures/planner/planned_moves.hpp"
#include "host/core/gcode.hpp"
#include "host/core/planner/planner.hpp"
#include "metrics/pulse/edge_index.hpp"
#include "metrics/pulse/sync_error.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {
namespace {

constexpr TimePs kScanStepPs = 100 * kPsPerUs;  // the ideal controller's scan (ideal_controller.cpp)

struct Circle {
    Scenario s;
    std::shared_ptr<const host::planner::Trajectory> traj;
    TimePs end_ps = 0;
    StepGrid grid;
};

Circle circle() {
    Circle c{load_scenario(std::string(CNC_SOURCE_DIR) + "/scenarios/ideal/circle_r10.toml", {}), nullptr, 0, {}};
    host::GcodeStream stream(c.s.job_path, c.s.interpreter, true);
    while (stream.next()) {
    }
    c.traj = std::make_shared<const host::planner::Trajectory>(
        host::planner::plan(stream.take(), c.s.settings<IdealSettings>().planner));
    c.end_ps = s_to_ps(c.traj->duration_s());
    c.grid = {c.s.interpreter.start_mm, {c.s.machine.x.steps_per_mm(), c.s.machine.y.steps_per_mm()}};
    return c;
}

// The ideal's pins over the whole job, as metrics::AxisTrace (DIR high is the positive direction: StepTrain's).
std::vector<metrics::AxisTrace> ideal_pins(const Circle& c) {
    const host::planner::PlannerConfig& cfg = c.s.settings<IdealSettings>().planner;
    ideal::IdealEdges edges(open_plan(c.s, cfg), c.grid, c.end_ps, kScanStepPs);
    std::vector<metrics::AxisTrace> axes{{"x", {"step_x", false, {}}, {"dir_x", false, {}}, c.grid.steps_per_mm[0]},
                                         {"y", {"step_y", false, {}}, {"dir_y", false, {}}, c.grid.steps_per_mm[1]}};
    for (std::optional<ideal::TimedEdge> e = edges.next(); e; e = edges.next()) {
        switch (e->pin) {
            case ideal::Pin::StepX:
                axes[0].step.add(e->t_ps, e->level);
                break;
            case ideal::Pin::DirX:
                axes[0].dir.add(e->t_ps, e->level);
                break;
            case ideal::Pin::StepY:
                axes[1].step.add(e->t_ps, e->level);
                break;
            case ideal::Pin::DirY:
                axes[1].dir.add(e->t_ps, e->level);
                break;
            case ideal::Pin::Laser:
                break;
        }
    }
    return axes;
}

// The sync error of each axis with the ideal's clock knotted as the controller knots it (tau = t at every slice
// end, then the job's end) at the ends of slices of the lengths given, the last one repeated.
std::vector<std::optional<double>> sync_ns(const Circle& c, const std::vector<metrics::AxisTrace>& axes,
                                           const std::vector<TimePs>& slices_ps) {
    host::servo::TrajectoryClock clock;
    clock.add(0, 0.0);
    TimePs t_ps = 0;
    for (std::size_t k = 0;; ++k) {
        t_ps += slices_ps[std::min(k, slices_ps.size() - 1)];
        if (t_ps >= c.end_ps) break;
        clock.add(t_ps, ps_to_s(t_ps));
    }
    clock.add(c.end_ps, ps_to_s(c.end_ps));
    metrics::RunInput in;
    in.axes = axes;
    in.t_job_end_ps = c.end_ps;
    const std::shared_ptr<host::planner::PlanFeed> plan = open_plan(c.s, c.s.settings<IdealSettings>().planner);
    PlannedMoves planned(*plan, c.grid);
    in.moves = planned.take(clock, true);
    in.commanded = commanded_as_planned(c.traj, clock, c.grid.origin_mm, kScanStepPs);
    return metrics::compute_sync(in, metrics::index_edges(in)).axis_max_abs_ns;
}

TEST(IdealCommanded, SyncErrorDoesNotDependOnWhereTheSlicesEnded) {
    const Circle c = circle();
    const std::vector<metrics::AxisTrace> axes = ideal_pins(c);
    // Slices at their 1 s cap (a light stretch of an unloaded run) and at the first slice's 10 ms (where a loaded
    // machine keeps them).
    const std::vector<std::optional<double>> unloaded = sync_ns(c, axes, {kPsPerSec});
    const std::vector<std::optional<double>> loaded = sync_ns(c, axes, {10 * kPsPerMs});
    ASSERT_EQ(unloaded.size(), 2U);
    ASSERT_EQ(loaded.size(), 2U);
    for (std::size_t a = 0; a < 2; ++a) {
        ASSERT_TRUE(unloaded[a].has_value()) << "axis " << a;
        ASSERT_TRUE(loaded[a].has_value()) << "axis " << a;
        EXPECT_EQ(*unloaded[a], *loaded[a]) << "axis " << a;
        EXPECT_EQ(*unloaded[a], 0.0) << "axis " << a;
    }
}

}  // namespace
}  // namespace cnc::sim
