#include "run/machine_run.hpp"

#include <optional>
#include <utility>
#include <vector>

#include "probes/edge_recorder.hpp"
#include "probes/vcd_trace.hpp"
#include "run/carriage_feed.hpp"
#include "run/mechanics_report.hpp"
#include "run/simulate.hpp"
#include "run/step_fault_report.hpp"

namespace cnc::sim {

namespace {

// The machine pins the recorder watches, in the order the metrics read them.
void record_pins(EdgeRecorder& rec, const MachinePins& pins, bool enable) {
    for (const sc_core::sc_signal<bool>* sig : {&pins.step_x, &pins.dir_x, &pins.step_y, &pins.dir_y}) {
        rec.watch(*sig, sig->basename());
    }
    if (enable) {
        for (const sc_core::sc_signal<bool>* sig : {&pins.n_enbl_x, &pins.n_enbl_y}) rec.watch(*sig, sig->basename());
    }
    rec.watch(pins.laser, pins.laser.basename());
}

// The VCD's pins: each DRV8825's STEP, DIR and nENBL and the laser head's input, each with the clock that times it,
// then the controller's own (its link, its FPGA's nets). The machine's come first: sigrok-cli 0.7.2 decodes a STEP
// pin declared after the link's lines wrongly (116 of 9600 rising edges on the 20 mm square over UART).
std::vector<TracedPin> traced_pins(const MachinePins& pins, const Controller& ctl) {
    const MachinePinClocks clocks = ctl.pin_clocks();
    const std::optional<std::int64_t> out = clocks.step_dir_laser_hz;
    std::vector<TracedPin> traced;
    for (const TracedPin& p : std::initializer_list<TracedPin>{{&pins.step_x, "driver_x", out},
                                                               {&pins.dir_x, "driver_x", out},
                                                               {&pins.n_enbl_x, "driver_x", clocks.enable_hz},
                                                               {&pins.step_y, "driver_y", out},
                                                               {&pins.dir_y, "driver_y", out},
                                                               {&pins.n_enbl_y, "driver_y", clocks.enable_hz},
                                                               {&pins.laser, "laser", out}}) {
        traced.push_back(p);
    }
    for (const TracedPin& p : ctl.traced_pins()) traced.push_back(p);
    return traced;
}

std::vector<AxisPins> axis_pins(const Scenario& s, bool dir_high_is_positive) {
    return {{"x", "step_x", "dir_x", s.machine.x.steps_per_mm(), dir_high_is_positive},
            {"y", "step_y", "dir_y", s.machine.y.steps_per_mm(), dir_high_is_positive}};
}

}  // namespace

ArchRun run_on_machine(const Scenario& s, const Job& job, const MakeController& make) {
    MachinePins pins;
    const std::unique_ptr<Controller> ctl = make(s, job, pins);
    mech::Drv8825Config driver = s.driver;
    driver.dir_high_is_positive = ctl->dir_high_is_positive();
    driver.step_loss_rate = s.faults.step_loss_rate;
    driver.fault_seed = s.faults.seed;
    Machine machine("machine", s.machine, driver, s.interpreter.start_mm, s.mechanics, !s.vcd_path.empty());
    machine.bind(pins);
    EdgeRecorder rec("probes");
    record_pins(rec, pins, ctl->drives_enable());
    ctl->record(rec, s.keep_run_input);
    std::unique_ptr<VcdTrace> vcd;
    if (!s.vcd_path.empty()) vcd = std::make_unique<VcdTrace>(s, traced_pins(pins, *ctl), machine.traced_positions());

    const RunBudget budget = run_budget(s, ctl->estimate());
    const std::vector<AxisPins> axes = axis_pins(s, ctl->dir_high_is_positive());
    // The metrics stream (their inputs dropped as they are measured) unless the whole logs are asked for.
    std::optional<MetricsFeed> feed;
    if (!s.keep_run_input) {
        feed_on_carriage(feed, rec, axes, machine, s.detail, ctl->on_piece_measured());
        ctl->feed_started(*feed);
    }
    const TimePs check_ps = ctl->stop_check_ps();
    const std::function<bool()> stopped = [&ctl] { return ctl->stopped(); };
    SimulationEnd end = simulate(budget, check_ps > 0 ? stopped : std::function<bool()>(), check_ps,
                                 [&](TimePs now_ps) { ctl->slice_ended(now_ps, feed ? &*feed : nullptr); });
    if (vcd) vcd->close();
    const TimePs stop_ps = end.t_ps;
    machine.finish_mechanics(end, budget.limit_ps, check_ps > 0);

    ArchRun run;
    if (vcd) run.trace = vcd->layout();
    record_budget(budget, run);
    ctl->simulation_ended(stop_ps);
    metrics::RunInput& in = run.input;
    in.t_job_start_ps = 0;
    in.t_job_end_ps = ctl->job_end_ps(end.t_ps);
    if (feed) {
        ctl->finish_feed(*feed);
        run.metrics = feed->finish(in.t_job_end_ps);
    } else {
        for (const AxisPins& a : axes) {
            in.axes.push_back({a.name, ctl->take_edges(rec, a.step_pin), ctl->take_edges(rec, a.dir_pin),
                               a.steps_per_mm, a.dir_high_is_positive});
        }
        in.tool = machine.carriage().samples();
        in.laser = ctl->take_edges(rec, "laser");
    }
    ctl->finish_input(in, feed.has_value());
    if (feed && !in.rate_segments.empty()) {
        // The axes' names label the report's commanded rates; their edges are measured and gone.
        for (const AxisPins& a : axes) in.axes.push_back({a.name, {}, {}, a.steps_per_mm, a.dir_high_is_positive});
    }
    if (!feed) {
        run.metrics = metrics::compute_metrics(in);
        ctl->measured(*run.metrics);
    }
    ctl->take_lines(rec, run.lines);
    ctl->report(run, budget, end);
    add_mechanics_report(machine, feed, run);
    if (s.faults.step_loss_rate > 0.0) add_step_fault_report(machine, s, run);
    return run;
}

}  // namespace cnc::sim
