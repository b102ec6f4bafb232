// What an architecture's system hands back after its simulation: the measured traces for the metrics, and its
// own report section (link, host, controller details) with its warnings.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/warning.hpp"
#include "metrics/run_input.hpp"

namespace cnc::sim {

struct ArchRun {
    metrics::RunInput input;
    std::map<std::string, EdgeLog> lines;               // other recorded pins (busy, UART lines), by name
    nlohmann::json details = nlohmann::json::object();  // architecture section of the JSON report
    std::string details_text;                           // the same, for the summary
    std::vector<Warning> warnings;  // grouped by kind in the reports (run.cpp)
    bool ok = true;
    std::string failure;
    double estimated_s = 0.0;  // the job's estimate and the simulated-time limit the run had (run/simulate.hpp)
    double max_sim_s = 0.0;
};

}  // namespace cnc::sim
