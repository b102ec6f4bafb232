#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

#include "architectures/planner/planned_job.hpp"
#include "architectures/planner/planned_moves.hpp"
#include "architectures/spi_fpga/rate_segments.hpp"
#include "architectures/spi_fpga/spi_faults.hpp"
#include "architectures/spi_fpga/spi_fpga.hpp"
#include "architectures/spi_fpga/spi_fpga_job.hpp"
#include "architectures/spi_fpga/spi_fpga_report.hpp"
#include "architectures/spi_fpga/spi_fpga_settings.hpp"
#include "fpga/spi/rtl_spi_top.hpp"
#include "fpga/spi/spi_fpga_top.hpp"
#include "host/servo/servo_thread.hpp"
#include "run/controller.hpp"
#include "run/machine_run.hpp"
#include "spi/spi_master.hpp"

namespace cnc::sim::spi_fpga {

namespace {

// The SPI wires (the machine's pins are the run's: run/machine.hpp); the VCD and the analyze scripts rely on the
// names (docs/architectures.md "Pins").
struct Wires {
    sc_core::sc_signal<bool> sclk{"sclk", false};  // mode 0: idles low
    sc_core::sc_signal<bool> mosi{"mosi", false};
    sc_core::sc_signal<bool> miso{"miso", false};
    sc_core::sc_signal<bool> ss{"ss", true};  // active low
};

host::servo::ServoConfig servo_config(const Scenario& s, const SpiFpgaSettings& f) {
    host::servo::ServoConfig c = f.servo;
    c.seed = s.seed;
    c.origin_mm = s.interpreter.start_mm;
    const host::AxisMachine* machine[] = {&s.machine.x, &s.machine.y};
    const host::planner::AxisLimits* limits[] = {&f.planner.x, &f.planner.y};
    for (std::size_t a = 0; a < host::servo::kAxes; ++a) {
        c.axes[a] = {machine[a]->steps_per_mm(), limits[a]->max_velocity_mm_per_s, limits[a]->max_accel_mm_per_s2};
    }
    return c;
}

// The FPGA as the scenario asks for it (fpga.model), its clock on the board's oscillator (the host's rate words stay
// nominal). The event model keeps no per-frame logs (the report counts the frames) and serves the master's
// transaction path when the wires are not driven; the Verilog needs the wires and runs ahead to the time the
// master promises them quiet.
std::unique_ptr<fpga::SpiBoard> make_fpga(const SpiFpgaSettings& f, std::uint64_t seed, spi::SpiMaster& master) {
    const fpga::SpiFpgaConfig cfg = on_oscillator(f.fpga, f.clock, seed);
    if (f.rtl.rtl) {
        auto rtl = std::make_unique<fpga::RtlSpiTop>("fpga", cfg, f.rtl.design);
        rtl->inputs_quiet_until([&master] { return master.pins_quiet_until(); });
        return rtl;
    }
    auto event = std::make_unique<fpga::SpiFpgaTop>("fpga", cfg);
    event->keep_frame_logs(false);
    if (!master.config().trace_wires) master.target(event->spi_target);
    return event;
}

// The seed 004 system between the job and the machine's pins: the planner and the servo thread on the host, the SPI
// master, the FPGA.
class SpiFpgaController final : public Controller {
public:
    // `ahead`: read_job_ahead().
    SpiFpgaController(const Scenario& s, MachinePins& pins, JobAhead ahead)
        : m_s(s),
          m_f(s.settings<SpiFpgaSettings>()),
          m_estimate(ahead.estimate),
          m_plan(open_plan(s, m_f.planner)),
          m_trajectory(m_plan, &m_plan->trajectory()),
          m_link(spi_link(s, m_f)),
          m_master("spi_master", m_link),
          m_fpga(make_fpga(m_f, s.seed, m_master)),
          m_host("host", servo_config(s, m_f), *m_plan, std::move(ahead.servo), m_master),
          m_planned(*m_plan, step_grid(s)),
          m_rate_feed(s.detail) {
        m_master.keep_transfer_log(false);  // the report counts them
        if (s.faults.spi_ber > 0.0) m_master.set_bit_faults(s.faults.spi_ber, s.faults.seed);
        m_master.sclk(m_wires.sclk);
        m_master.mosi(m_wires.mosi);
        m_master.ss(m_wires.ss);
        m_master.miso(m_wires.miso);
        m_fpga->sclk(m_wires.sclk);
        m_fpga->mosi(m_wires.mosi);
        m_fpga->ss(m_wires.ss);
        m_fpga->miso(m_wires.miso);
        m_fpga->step_x(pins.step_x);
        m_fpga->dir_x(pins.dir_x);
        m_fpga->step_y(pins.step_y);
        m_fpga->dir_y(pins.dir_y);
        m_fpga->laser(pins.laser);  // the FPGA's laser_latch (the frame's laser bit)
        m_host.keep_wakeups(s.detail);  // the report's summary is folded period by period; --detail lists every one
    }

    // The FPGA times its step, dir and laser outputs and drives no EN pin.
    [[nodiscard]] MachinePinClocks pin_clocks() const override {
        return {fpga::clock_grid(m_fpga->config()).grid_hz(), std::nullopt};
    }
    // The host's servo thread times the SPI master (sclk, mosi, ss); the FPGA answers on miso at SS edges as well as
    // on its clock. The SPI wires toggle only when they are driven bit by bit, which costs simulation time: they
    // are traced when asked for (trace.signals, spi.trace_wires).
    [[nodiscard]] std::vector<TracedPin> traced_pins() const override {
        const bool on_request = !m_link.trace_wires;
        return {{&m_wires.sclk, "link", {}, on_request},
                {&m_wires.mosi, "link", {}, on_request},
                {&m_wires.miso, "link", {}, on_request},
                {&m_wires.ss, "link", {}, on_request}};
    }
    void record(EdgeRecorder& rec, bool) override {
        if (!m_link.trace_wires) return;
        for (const sc_core::sc_signal<bool>* sig : {&m_wires.sclk, &m_wires.mosi, &m_wires.miso, &m_wires.ss}) {
            rec.watch(*sig, sig->basename());
        }
    }

    [[nodiscard]] JobEstimate estimate() const override { return m_estimate; }
    void feed_started(MetricsFeed& feed) override {
        feed.pending().commanded =
            commanded_trajectory_live(m_trajectory, m_host.core().clock(), origin(), m_f.servo.period_ps);
    }
    void slice_ended(TimePs now_ps, MetricsFeed* feed) override {
        if (feed == nullptr) return;
        hand_over(*feed, false);
        feed->fold(now_ps);
        // The clock's knots that neither the metrics (behind the simulation while the carriage's samples are not
        // ready) nor the moves still to be handed over read, and the pieces of plan behind the metrics (the servo
        // and the laser bit read from the clock's tau on).
        const TimePs read_from_ps = commanded_read_from(feed->pending(), feed->measured_ps());
        const PlannedMoves::ClockNeeded needed = m_planned.clock_needed();
        m_host.drop_clock_before(std::min(read_from_ps, needed.t_ps), needed.tau_s);
        m_plan->drop_before(m_host.core().clock().tau_at(read_from_ps));
    }

    [[nodiscard]] TimePs job_end_ps(TimePs stop_ps) const override { return m_host.t_done_ps().value_or(stop_ps); }
    void finish_feed(MetricsFeed& feed) override { hand_over(feed, true); }
    void finish_input(metrics::RunInput& in, bool streamed) override {
        if (streamed) {
            in.rate_segments = m_rate_feed.take_kept();
            return;
        }
        const host::servo::ServoCore& core = m_host.core();
        in.moves = m_planned.take(core.clock(), true);
        in.commanded = commanded_trajectory(m_trajectory, core.clock(), origin(), m_f.servo.period_ps);
        in.rate_segments = m_segments.take(*m_fpga, core, true);
    }
    void take_lines(EdgeRecorder& rec, std::map<std::string, EdgeLog>& lines) override {
        if (!m_link.trace_wires) return;
        for (const char* pin : {"sclk", "mosi", "miso", "ss"}) lines[pin] = rec.take(pin);
    }
    void report(ArchRun& run, const RunBudget& budget, const SimulationEnd& end) override {
        SpiFpgaReport report = spi_fpga_report(m_host, m_master, *m_fpga, run.input.t_job_end_ps, m_s.detail);
        run.details = std::move(report.details);
        run.details_text = std::move(report.text);
        const ClockGrid clock = fpga::clock_grid(m_fpga->config());
        run.clock = oscillator_json(m_f.clock, clock);
        run.clock_text = oscillator_text(m_f.clock, clock);
        run.warnings = std::move(report.warnings);
        if (m_s.faults.spi_ber > 0.0) report_spi_faults(m_s.faults, m_master, m_fpga->stats(), run);
        if (!m_host.finished()) {
            run.ok = false;
            run.failure = "the job did not finish (the axes had not landed): " + time_limit_text(budget, end);
        }
    }

private:
    // The commanded trajectory from the machine's origin; scanned a servo period at a time, within which tau is
    // linear, so that an axis velocity turns at most once.
    [[nodiscard]] geom::Vec2 origin() const { return m_s.interpreter.start_mm; }
    static StepGrid step_grid(const Scenario& s) {
        return {s.interpreter.start_mm, {s.machine.x.steps_per_mm(), s.machine.y.steps_per_mm()}};
    }
    // The Verilog has only the wires (no transaction path): it drives them, as spi.trace_wires does.
    static spi::SpiConfig spi_link(const Scenario& s, const SpiFpgaSettings& f) {
        spi::SpiConfig link = f.link;
        link.trace_wires =
            link.trace_wires || f.rtl.rtl || trace_names_any(s, "link", {"sclk", "mosi", "miso", "ss"});
        return link;
    }

    // The moves and rate segments closed so far to the streaming metrics. The rate segments stay whole for --detail,
    // whose report lists them (commanded_rates).
    void hand_over(MetricsFeed& feed, bool ended) {
        const host::servo::ServoCore& core = m_host.core();
        for (metrics::MoveSpec& m : m_planned.take(core.clock(), ended)) feed.add_piece(std::move(m));
        const std::vector<std::vector<metrics::RateSegment>> closed = m_segments.take(*m_fpga, core, ended);
        m_rate_feed.hand_over(feed, closed);
        commanded_known(*feed.pending().commanded, core.clock());
        if (!m_s.detail) m_host.drop_log_before(m_segments.first_needed_period());  // --detail lists every period
    }

    const Scenario& m_s;
    const SpiFpgaSettings& m_f;
    JobEstimate m_estimate;
    const std::shared_ptr<host::planner::PlanFeed> m_plan;
    // The commanded trajectory's readings share the plan (they are read after the run).
    const std::shared_ptr<const host::planner::Trajectory> m_trajectory;
    const spi::SpiConfig m_link;
    Wires m_wires;
    spi::SpiMaster m_master;
    std::unique_ptr<fpga::SpiBoard> m_fpga;
    host::servo::ServoThread m_host;
    PlannedMoves m_planned;
    RateSegments m_segments;
    RateSegmentFeed m_rate_feed;
};

}  // namespace

ArchRun Entry::run(const Scenario& s, const Job& job) {
    return run_on_machine(s, job, [](const Scenario& sc, const Job& j, MachinePins& pins) {
        const SpiFpgaSettings& f = sc.settings<SpiFpgaSettings>();
        check_rate_limits(f, sc.machine, sc.file);
        return std::make_unique<SpiFpgaController>(sc, pins, read_job_ahead(sc, j, f.planner));
    });
}

}  // namespace cnc::sim::spi_fpga
