// Runs a scenario: loads the job, hands it to the architecture's system, measures, reports.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "metrics/metrics.hpp"
#include "run/arch_run.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

struct RunOutcome {
    bool ok = true;
    std::string failure;      // why the run failed (the job did not complete as the host intended)
    std::string summary;      // the text the CLI prints
    nlohmann::json report;    // the JSON report (same numbers)
    ArchRun arch;             // the measured traces and the architecture's own section
    metrics::RunMetrics metrics;
};

RunOutcome run_scenario(const Scenario& scenario);

}  // namespace cnc::sim
