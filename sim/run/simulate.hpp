// Runs an elaborated system to its end, the one way every architecture does: to the simulated-time limit,
// until the kernel has no event left, or until the model says it is done; with the progress display.
#pragma once
#include <functional>
#include <string>

#include "common/units.hpp"
#include "run/arch_run.hpp"
#include "run/job_estimate.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

struct RunBudget {
    JobEstimate estimate;
    TimePs limit_ps = 0;  // scenario.max_sim_s when the scenario sets it, else the estimate's limit
    bool limit_from_scenario = false;
    ProgressStyle progress = ProgressStyle::Off;
    std::string label;  // names the run in its progress lines (the architecture)
};

[[nodiscard]] RunBudget run_budget(const Scenario& scenario, const JobEstimate& estimate);

struct SimulationEnd {
    TimePs t_ps = 0;  // simulated time when the run stopped
    bool limit_reached = false;
};

// sc_start in slices, so that the progress display can follow between them; a slice boundary adds no event
// and the model runs exactly as under one sc_start. `finished` (may be empty) is asked every `check_ps` of
// simulated time (the slices are then that long, from time 0); without it the slices grow or shrink to about
// a tenth of a second of wall time each. `after_slice` (may be empty) is called after each slice with the simulated
// time reached: where a run hands what it recorded to its streaming metrics (metrics/streaming/metrics_stream.hpp).
SimulationEnd simulate(const RunBudget& budget, const std::function<bool()>& finished = {}, TimePs check_ps = 0,
                       const std::function<void(TimePs)>& after_slice = {});

// The estimate and the limit, for the run's report.
void record_budget(const RunBudget& budget, ArchRun& run);

// Why a run that did not finish stopped: the simulated time it reached, the limit and where it came from, and
// the key to raise.
[[nodiscard]] std::string time_limit_text(const RunBudget& budget, const SimulationEnd& end);

}  // namespace cnc::sim
