#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <systemc>

#include <fmt/format.h>

#include "architectures/ideal/ideal.hpp"
#include "architectures/ideal/ideal_edges.hpp"
#include "architectures/ideal/ideal_settings.hpp"
#include "architectures/planner/planned_job.hpp"
#include "architectures/planner/planned_moves.hpp"
#include "common/sc_time.hpp"
#include "run/controller.hpp"
#include "run/machine_run.hpp"

namespace cnc::sim::ideal {

namespace {

// The crossings are searched 100 us of trajectory at a time: within it an axis velocity turns at most once unless
// the axis reverses within 100 us, which the planner's acceleration limit allows only over a few thousandths of a
// step (at 1000 mm/s^2 and 160 steps/mm, a^2 dt^2 / 4 = 4e-4 steps): too small a travel to cross a step level twice.
constexpr TimePs kScanStepPs = 100 * kPsPerUs;

// Drives the pins with the edges IdealEdges makes, each at its instant.
class IdealStepGenerator : public sc_core::sc_module {
public:
    sc_core::sc_out<bool> step_x, dir_x, step_y, dir_y, laser;

    IdealStepGenerator(const sc_core::sc_module_name& name, IdealEdges& edges)
        : sc_module(name),
          step_x("step_x"),
          dir_x("dir_x"),
          step_y("step_y"),
          dir_y("dir_y"),
          laser("laser"),
          m_edges(edges) {
        SC_HAS_PROCESS(IdealStepGenerator);
        SC_THREAD(drive);
    }

    // Every edge of the job has been driven.
    [[nodiscard]] bool finished() const { return m_finished; }

private:
    void drive() {
        for (std::optional<TimedEdge> e = m_edges.next(); e; e = m_edges.next()) {
            wait_ps(e->t_ps - now_ps());
            pin(e->pin).write(e->level);
        }
        m_finished = true;
    }
    sc_core::sc_out<bool>& pin(Pin p) {
        switch (p) {
            case Pin::StepX:
                return step_x;
            case Pin::DirX:
                return dir_x;
            case Pin::StepY:
                return step_y;
            case Pin::DirY:
                return dir_y;
            case Pin::Laser:
                break;
        }
        return laser;
    }

    IdealEdges& m_edges;
    bool m_finished = false;
};

// The whole job planned once before the run (the planner's BadInput before anything is simulated): its end.
TimePs planned_end_ps(const Scenario& s, const host::planner::PlannerConfig& cfg) {
    const std::shared_ptr<host::planner::PlanFeed> plan = open_plan(s, cfg);
    while (plan->plan_next()) {
        const std::vector<host::planner::PlannedPiece>& pieces = plan->trajectory().pieces();
        if (!pieces.empty()) plan->drop_before(pieces.back().t_begin_s);
        plan->drop_moves_before(std::numeric_limits<std::size_t>::max());
    }
    return s_to_ps(plan->trajectory().duration_s());
}

// The perfect controller between the job and the machine's pins: the planned trajectory, stepped at its half-step
// crossings.
class IdealController final : public Controller {
public:
    IdealController(const Scenario& s, const Job& job, MachinePins& pins, TimePs end_ps)
        : m_s(s),
          m_settings(s.settings<IdealSettings>()),
          m_estimate(planned_estimate(s, job, m_settings.planner)),
          m_end_ps(end_ps),
          m_plan(open_plan(s, m_settings.planner)),
          m_trajectory(m_plan, &m_plan->trajectory()),
          m_grid{s.interpreter.start_mm, {s.machine.x.steps_per_mm(), s.machine.y.steps_per_mm()}},
          m_edges(m_plan, m_grid, end_ps, kScanStepPs),
          m_generator("ideal", m_edges),
          m_planned(*m_plan, m_grid),
          m_rate_feed(s.detail) {
        m_generator.step_x(pins.step_x);
        m_generator.dir_x(pins.dir_x);
        m_generator.step_y(pins.step_y);
        m_generator.dir_y(pins.dir_y);
        m_generator.laser(pins.laser);
        m_clock.add(0, 0.0);  // the plan runs as planned: tau = t
    }

    // Every edge at its own instant, on no clock; no EN pin.
    [[nodiscard]] MachinePinClocks pin_clocks() const override { return {}; }

    [[nodiscard]] JobEstimate estimate() const override { return m_estimate; }
    void feed_started(MetricsFeed& feed) override {
        feed.pending().commanded = commanded_as_planned(m_trajectory, m_clock, m_grid.origin_mm, kScanStepPs);
    }
    void slice_ended(TimePs now_ps, MetricsFeed* feed) override {
        m_clock.add(now_ps, ps_to_s(now_ps));
        if (feed == nullptr) return;
        hand_over(*feed, now_ps, false);
        feed->fold(now_ps);
        // What neither the metrics nor the moves still to be handed over read of the clock and the plan.
        const TimePs read_from_ps = commanded_read_from(feed->pending(), feed->measured_ps());
        const PlannedMoves::ClockNeeded needed = m_planned.clock_needed();
        m_clock.drop_before(std::min(read_from_ps, needed.t_ps), needed.tau_s);
        if (read_from_ps > 0) m_plan->drop_before(ps_to_s(read_from_ps));
    }

    void simulation_ended(TimePs stop_ps) override {
        const TimePs end_ps = std::max(stop_ps, m_end_ps);
        if (end_ps > m_clock.t_end_ps()) m_clock.add(end_ps, ps_to_s(end_ps));
    }
    [[nodiscard]] TimePs job_end_ps(TimePs stop_ps) const override {
        return m_generator.finished() ? m_end_ps : stop_ps;
    }
    void finish_feed(MetricsFeed& feed) override { hand_over(feed, std::numeric_limits<TimePs>::max(), true); }
    void finish_input(metrics::RunInput& in, bool streamed) override {
        if (streamed) {
            in.rate_segments = m_rate_feed.take_kept();
            return;
        }
        in.moves = m_planned.take(m_clock, true);
        in.commanded = commanded_as_planned(m_trajectory, m_clock, m_grid.origin_mm, kScanStepPs);
        in.rate_segments = m_edges.take_rate_segments(std::numeric_limits<TimePs>::max());
    }
    void report(ArchRun& run, const RunBudget& budget, const SimulationEnd& end) override {
        const double duration_s = ps_to_s(m_end_ps);
        run.details = {{"trajectory_s", duration_s}, {"scan_step_us", ps_to_us(kScanStepPs)}};
        run.details_text = fmt::format(
            FMT_STRING("ideal: the planned trajectory, {:.6f} s, stepped at its half-step crossings\n"), duration_s);
        if (!m_generator.finished()) {
            run.ok = false;
            run.failure = "the job did not finish: " + time_limit_text(budget, end);
        }
    }

private:
    // The moves the clock has left and the rate segments begun before now_ps, to the streaming metrics. The rate
    // segments stay whole for --detail, whose report lists them (commanded_rates).
    void hand_over(MetricsFeed& feed, TimePs now_ps, bool ended) {
        for (metrics::MoveSpec& m : m_planned.take(m_clock, ended)) feed.add_piece(std::move(m));
        const std::vector<std::vector<metrics::RateSegment>> begun = m_edges.take_rate_segments(now_ps);
        m_rate_feed.hand_over(feed, begun);
        commanded_known(*feed.pending().commanded, m_clock);
    }

    const Scenario& m_s;
    const IdealSettings& m_settings;
    JobEstimate m_estimate;
    TimePs m_end_ps;
    const std::shared_ptr<host::planner::PlanFeed> m_plan;
    // The commanded trajectory's readings share the plan (they are read after the run).
    const std::shared_ptr<const host::planner::Trajectory> m_trajectory;
    StepGrid m_grid;
    host::servo::TrajectoryClock m_clock;
    IdealEdges m_edges;
    IdealStepGenerator m_generator;
    PlannedMoves m_planned;
    RateSegmentFeed m_rate_feed;
};

}  // namespace

ArchRun Entry::run(const Scenario& s, const Job& job) {
    return run_on_machine(s, job, [](const Scenario& sc, const Job& j, MachinePins& pins) {
        return std::make_unique<IdealController>(sc, j, pins, planned_end_ps(sc, sc.settings<IdealSettings>().planner));
    });
}

}  // namespace cnc::sim::ideal
