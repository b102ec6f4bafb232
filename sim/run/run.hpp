// Runs a scenario: loads the job, hands it to the architecture's system, measures, reports.
#pragma once
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "metrics/metrics.hpp"
#include "run/arch_run.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

struct RunOutcome {
    bool ok = true;
    std::string failure;  // why the run failed (the job did not complete as the host intended)
    std::string summary;  // the text the CLI prints
    bool detail = false;  // the report's detail (Scenario::detail)
    // The JSON report (same numbers) but the programmed moves' columns, which write_report() takes from `metrics`.
    nlohmann::json report;
    ArchRun arch;  // the measured traces and the architecture's own section
    metrics::RunMetrics metrics;
};

RunOutcome run_scenario(const Scenario& scenario);
// Writes the run's report file text: `report` with the moves' columns from metrics::RunMetrics::moves.
void write_report(std::ostream& out, const RunOutcome& run);

}  // namespace cnc::sim
