#include "systems/spi_fpga/spi_fpga_system.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

#include "common/bad_input.hpp"
#include "fpga/spi/spi_fpga_top.hpp"
#include "host/core/planner/speed_profile.hpp"
#include "host/servo/servo_thread.hpp"
#include "probes/edge_recorder.hpp"
#include "probes/vcd_trace.hpp"
#include "systems/carriage_feed.hpp"
#include "run/simulate.hpp"
#include "spi/spi_master.hpp"
#include "systems/machine.hpp"
#include "systems/spi_fpga/planned_moves.hpp"
#include "systems/spi_fpga/spi_fpga_job.hpp"
#include "systems/spi_fpga/spi_fpga_report.hpp"
#include "systems/mechanics_report.hpp"

namespace cnc::sim {

namespace {

// Every wire of the system: the machine pins named as in every architecture, then the link (README "Pins"; VCD
// and analyze scripts rely on the names).
struct Wires {
    sc_core::sc_signal<bool> step_x{"step_x", false}, dir_x{"dir_x", false};
    sc_core::sc_signal<bool> step_y{"step_y", false}, dir_y{"dir_y", false};
    // The FPGA drives no EN pin: the DRV8825s' nENBL stay low (enabled), held here as constant wires.
    sc_core::sc_signal<bool> n_enbl_x{"n_enbl_x", false}, n_enbl_y{"n_enbl_y", false};
    sc_core::sc_signal<bool> laser{"laser", false};  // the FPGA's laser_latch (the frame's laser bit)
    sc_core::sc_signal<bool> sclk{"sclk", false};    // mode 0: idles low
    sc_core::sc_signal<bool> mosi{"mosi", false};
    sc_core::sc_signal<bool> miso{"miso", false};
    sc_core::sc_signal<bool> ss{"ss", true};         // active low
};

// The VCD's pins, each with the clock that times its edges: the FPGA's for its step, dir and laser outputs. The
// host's servo thread times the SPI master (sclk, mosi, ss), the FPGA answers on miso at SS edges as well as on
// its clock, and the nENBL wires are constant. The SPI wires toggle only when they are driven bit by bit, which
// costs simulation time: they are traced when asked for (trace.signals, spi.trace_wires).
std::vector<TracedPin> traced_pins(const Wires& w, std::int64_t fpga_clock_hz, bool wires_driven) {
    const std::optional<std::int64_t> fpga = fpga_clock_hz;
    const bool on_request = !wires_driven;
    return {{&w.step_x, fpga},   {&w.dir_x, fpga},    {&w.step_y, fpga},         {&w.dir_y, fpga},
            {&w.n_enbl_x, {}},   {&w.n_enbl_y, {}},   {&w.laser, fpga},          {&w.sclk, {}, on_request},
            {&w.mosi, {}, on_request}, {&w.miso, {}, on_request}, {&w.ss, {}, on_request}};
}

host::servo::ServoConfig servo_config(const Scenario& s) {
    host::servo::ServoConfig c = s.spi_fpga.servo;
    c.seed = s.seed;
    c.origin_mm = s.interpreter.start_mm;
    const host::AxisMachine* machine[] = {&s.machine.x, &s.machine.y};
    const host::planner::AxisLimits* limits[] = {&s.spi_fpga.planner.x, &s.spi_fpga.planner.y};
    for (std::size_t a = 0; a < host::servo::kAxes; ++a) {
        c.axes[a] = {machine[a]->steps_per_mm(), limits[a]->max_velocity_mm_per_s, limits[a]->max_accel_mm_per_s2};
    }
    return c;
}

// The spi-fpga side of the job estimate: the planner holds each axis to its velocity limit, and a move that
// starts and ends at rest (exact stop; blended corners are faster) spends the time of one speed change from
// rest beyond length / speed. That change is taken at the smallest tangential acceleration the planner uses
// (half the smaller axis limit, on arcs: path_limits.hpp) and the smaller jerk limit.
ArchPace pace(const host::planner::PlannerConfig& cfg) {
    ArchPace p;
    p.max_speed_x_mm_per_s = cfg.x.max_velocity_mm_per_s;
    p.max_speed_y_mm_per_s = cfg.y.max_velocity_mm_per_s;
    host::planner::PathLimits slowest{};
    slowest.accel_mm_per_s2 = 0.5 * std::min(cfg.x.max_accel_mm_per_s2, cfg.y.max_accel_mm_per_s2);
    slowest.jerk_mm_per_s3 = std::min(cfg.x.max_jerk_mm_per_s3, cfg.y.max_jerk_mm_per_s3);
    p.ramp_s = [profile = cfg.profile, slowest](double speed_mm_per_s) {
        return host::planner::transition_time_s(profile, 0.0, speed_mm_per_s, slowest);
    };
    return p;
}

}  // namespace

ArchRun run_spi_fpga(const Scenario& s, const Job& job) {
    if (!job.program) {
        throw BadInput(s.file + ": scenario.job",
                       "spi-fpga needs a G-code job: its host plans the programmed moves (a seed 000 steps file "
                       "holds only the fpga-uart packets)");
    }
    check_rate_limits(s.spi_fpga, s.machine, s.file);
    JobAhead ahead = read_job_ahead(s, job, pace(s.spi_fpga.planner));
    const std::shared_ptr<host::planner::PlanFeed> plan = open_plan(s);
    // The commanded trajectory's readings share the plan (they are read after the run).
    const std::shared_ptr<const host::planner::Trajectory> trajectory(plan, &plan->trajectory());

    spi::SpiConfig link = s.spi_fpga.link;
    link.trace_wires = link.trace_wires || trace_names_any(s, {"sclk", "mosi", "miso", "ss"});

    Wires w;
    spi::SpiMaster master("spi_master", link);
    master.keep_transfer_log(false);  // the report counts them
    master.sclk(w.sclk);
    master.mosi(w.mosi);
    master.ss(w.ss);
    master.miso(w.miso);
    fpga::SpiFpgaTop fpga("fpga", s.spi_fpga.fpga);
    fpga.keep_frame_logs(false);  // the report counts the frames
    fpga.sclk(w.sclk);
    fpga.mosi(w.mosi);
    fpga.ss(w.ss);
    fpga.miso(w.miso);
    fpga.step_x(w.step_x);
    fpga.dir_x(w.dir_x);
    fpga.step_y(w.step_y);
    fpga.dir_y(w.dir_y);
    fpga.laser(w.laser);
    master.target(fpga.spi_target);
    host::servo::ServoThread host("host", servo_config(s), *plan, std::move(ahead.servo), master);
    host.keep_wakeups(s.detail);  // the report's summary is folded period by period; --detail lists every one
    Machine machine("machine", s.machine, s.driver, s.interpreter.start_mm, s.mechanics, !s.vcd_path.empty());
    machine.step_x(w.step_x);
    machine.dir_x(w.dir_x);
    machine.n_enbl_x(w.n_enbl_x);
    machine.step_y(w.step_y);
    machine.dir_y(w.dir_y);
    machine.n_enbl_y(w.n_enbl_y);
    machine.laser(w.laser);

    EdgeRecorder rec("probes");
    for (const sc_core::sc_signal<bool>* sig : {&w.step_x, &w.dir_x, &w.step_y, &w.dir_y, &w.laser}) {
        rec.watch(*sig, sig->basename());
    }
    if (link.trace_wires) {
        for (const sc_core::sc_signal<bool>* sig : {&w.sclk, &w.mosi, &w.miso, &w.ss}) rec.watch(*sig, sig->basename());
    }
    std::unique_ptr<VcdTrace> vcd;
    if (!s.vcd_path.empty()) {
        vcd = std::make_unique<VcdTrace>(s, traced_pins(w, s.spi_fpga.fpga.clk_hz, link.trace_wires),
                                         machine.traced_positions());
    }

    const RunBudget budget = run_budget(s, ahead.estimate);
    const host::servo::ServoCore& core = host.core();
    PlannedMoves planned(*plan);
    RateSegments segments;
    ArchRun run;
    metrics::RunInput& in = run.input;
    // The metrics stream (their inputs dropped as they are measured) unless the whole logs are asked for. The rate
    // segments stay whole for --detail, whose report lists them (commanded_rates).
    std::optional<MetricsFeed> feed;
    const auto hand_over = [&](bool ended) {
        for (metrics::MoveSpec& m : planned.take(core, ended)) feed->add_piece(std::move(m));
        const std::vector<std::vector<metrics::RateSegment>> closed = segments.take(fpga, core, ended);
        metrics::RunInput& pending = feed->pending();
        pending.rate_segments.resize(closed.size());
        in.rate_segments.resize(closed.size());  // the report's commanded_rates: null without --detail
        for (std::size_t a = 0; a < closed.size(); ++a) {
            pending.rate_segments[a].insert(pending.rate_segments[a].end(), closed[a].begin(), closed[a].end());
            if (s.detail) in.rate_segments[a].insert(in.rate_segments[a].end(), closed[a].begin(), closed[a].end());
        }
        commanded_known(*pending.commanded, core);
        if (!s.detail) host.drop_log_before(segments.first_needed_period());  // --detail lists every period
    };
    if (!s.keep_run_input) {
        const std::vector<AxisPins> axes{{"x", "step_x", "dir_x", s.machine.x.steps_per_mm()},
                                         {"y", "step_y", "dir_y", s.machine.y.steps_per_mm()}};
        feed_on_carriage(feed, rec, axes, machine, s.detail);
        feed->pending().commanded = commanded_trajectory_live(trajectory, core);
    }
    SimulationEnd end = simulate(budget, {}, 0, [&](TimePs now_ps) {
        if (!feed) return;
        hand_over(false);
        feed->fold(now_ps);
        // The clock's knots that neither the metrics (behind the simulation while the carriage's samples are not
        // ready) nor the moves still to be handed over read, and the pieces of plan behind the metrics (the servo
        // and the laser bit read from the clock's tau on).
        const TimePs read_from_ps = commanded_read_from(feed->pending(), feed->measured_ps());
        const PlannedMoves::ClockNeeded needed = planned.clock_needed();
        host.drop_clock_before(std::min(read_from_ps, needed.t_ps), needed.tau_s);
        plan->drop_before(core.clock().tau_at(read_from_ps));
    });
    if (vcd) vcd->close();
    machine.finish_mechanics(end, budget.limit_ps, false);

    record_budget(budget, run);
    in.t_job_start_ps = 0;
    in.t_job_end_ps = host.t_done_ps().value_or(end.t_ps);
    if (feed) {
        hand_over(true);
        run.metrics = feed->finish(in.t_job_end_ps);
        // The axes' names label the report's commanded_rates; their edges are measured and gone.
        in.axes.push_back({"x", {}, {}, s.machine.x.steps_per_mm(), true});
        in.axes.push_back({"y", {}, {}, s.machine.y.steps_per_mm(), true});
    } else {
        in.axes.push_back({"x", rec.take("step_x"), rec.take("dir_x"), s.machine.x.steps_per_mm(), true});
        in.axes.push_back({"y", rec.take("step_y"), rec.take("dir_y"), s.machine.y.steps_per_mm(), true});
        in.moves = planned.take(core, true);
        in.tool = machine.carriage().samples();
        in.laser = rec.take("laser");
        in.commanded = commanded_trajectory(trajectory, core);
        in.rate_segments = segments.take(fpga, core, true);
    }
    if (link.trace_wires) {
        for (const char* pin : {"sclk", "mosi", "miso", "ss"}) run.lines[pin] = rec.take(pin);
    }

    SpiFpgaReport report = spi_fpga_report(host, master, fpga, in.t_job_end_ps, s.detail);
    run.details = std::move(report.details);
    run.details_text = std::move(report.text);
    add_mechanics_report(machine, feed, run);
    run.warnings = std::move(report.warnings);
    if (!host.finished()) {
        run.ok = false;
        run.failure = "the job did not finish (the axes had not landed): " + time_limit_text(budget, end);
    }
    return run;
}

}  // namespace cnc::sim
