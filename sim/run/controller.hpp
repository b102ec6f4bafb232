// An architecture's controller as elaborated for one run: its own modules (host, link, FPGA or MCU) between the job
// and the machine's pins, and what the run pipeline (run/machine_run.hpp) asks of it before, during and after the
// simulation. The pipeline owns what every architecture shares: the machine and its pins, the edge recorder, the
// VCD, the time budget, the streaming metrics, the mechanics' end and report.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/edge_log.hpp"
#include "metrics/metrics.hpp"
#include "metrics/run_input.hpp"
#include "metrics/streaming/metrics_stream.hpp"
#include "probes/edge_recorder.hpp"
#include "probes/vcd_trace.hpp"
#include "run/arch_run.hpp"
#include "run/job_estimate.hpp"
#include "run/metrics_feed.hpp"
#include "run/simulate.hpp"

namespace cnc::sim {

// The clocks that time the machine pins a controller drives, for the VCD (TracedPin::clock_hz); none: host timing
// or a constant level.
struct MachinePinClocks {
    std::optional<std::int64_t> step_dir_laser_hz;  // STEP, DIR and the laser pin
    std::optional<std::int64_t> enable_hz;          // nENBL
};

class Controller {
public:
    virtual ~Controller() = default;

    // --- Elaboration (the controller is built and bound to the machine's pins; the machine and recorder follow.)
    [[nodiscard]] virtual MachinePinClocks pin_clocks() const = 0;
    // Its own wires in the VCD, each in the scope of its hardware block (link, fpga; docs/vcd.md), after the
    // machine's pins.
    [[nodiscard]] virtual std::vector<TracedPin> traced_pins() const { return {}; }
    // The DIR level that moves an axis the positive way: the DRV8825s are wired so, and the metrics read DIR so.
    [[nodiscard]] virtual bool dir_high_is_positive() const { return true; }
    // It drives nENBL to stop its axes: the recorder watches nENBL too, for the STEP pulses the drivers take.
    [[nodiscard]] virtual bool drives_enable() const { return false; }
    // The recorder watches the machine's pins; the controller adds its own lines, and keeps what it reads of the
    // recorder (`whole_logs`: every edge is kept for after the run, and the metrics do not stream).
    virtual void record(EdgeRecorder& /*rec*/, bool /*whole_logs*/) {}

    // --- The run
    // The job's estimate: the time budget and the progress display.
    [[nodiscard]] virtual JobEstimate estimate() const = 0;
    // How often, in simulated time, the run asks stopped(); 0: the run ends when the kernel has no event left, or
    // at the time limit.
    [[nodiscard]] virtual TimePs stop_check_ps() const { return 0; }
    [[nodiscard]] virtual bool stopped() { return false; }
    // The streaming metrics (not when the whole logs are kept): what is told of each executed piece they measured,
    // and the feed once it is started, before the simulation.
    [[nodiscard]] virtual metrics::PieceMeasured on_piece_measured() { return {}; }
    virtual void feed_started(MetricsFeed& /*feed*/) {}
    // After each slice of the simulation, at now_ps; `feed` is the streaming metrics, null with the whole logs.
    virtual void slice_ended(TimePs now_ps, MetricsFeed* feed) = 0;

    // --- After the simulation (the mechanics have finished)
    // Reads what is left of its models' records; `stop_ps` is when the simulation stopped.
    virtual void simulation_ended(TimePs /*stop_ps*/) {}
    // When the job ended: its host's or firmware's end, or `stop_ps` when it did not get there.
    [[nodiscard]] virtual TimePs job_end_ps(TimePs stop_ps) const = 0;
    // Streamed: the pieces it has not handed to the feed yet.
    virtual void finish_feed(MetricsFeed& /*feed*/) {}
    // Its part of the run's input beyond the pins: with the whole logs, what the metrics read (the executed pieces,
    // a commanded trajectory, rate segments); streamed, what the report still reads.
    virtual void finish_input(metrics::RunInput& /*in*/, bool /*streamed*/) {}
    // With the whole logs: a machine pin's edges for the metrics (the recorder's, or what the controller made of
    // them).
    [[nodiscard]] virtual EdgeLog take_edges(EdgeRecorder& rec, const std::string& pin) { return rec.take(pin); }
    // With the whole logs: the metrics computed from them.
    virtual void measured(const metrics::RunMetrics& /*m*/) {}
    // Its own recorded lines, by name (ArchRun::lines).
    virtual void take_lines(EdgeRecorder& /*rec*/, std::map<std::string, EdgeLog>& /*lines*/) {}
    // Its report section (ArchRun::details and details_text), its warnings, and whether the run failed.
    virtual void report(ArchRun& run, const RunBudget& budget, const SimulationEnd& end) = 0;
};

}  // namespace cnc::sim
