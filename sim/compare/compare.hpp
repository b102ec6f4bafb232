// cncsim compare: one job on one machine through several architectures, side by side (DESIGN.md §6). Each
// architecture runs in its own child process (`cncsim run`), since SystemC allows one elaboration per process.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cnc::sim {

struct CompareColumn {
    std::string architecture;
    int exit_code = 0;        // of the child `cncsim run`: 0 ok, 1 run failed, 2 bad input
    nlohmann::json report;    // its JSON report (null when it wrote none)
};

enum class TableFormat { Text, Markdown, Csv, Json };

// Runs `self_exe run SCENARIO --set scenario.architecture=A [--set ...] --report TMP` for each architecture.
std::vector<CompareColumn> run_compare(const std::string& self_exe, const std::string& scenario,
                                       const std::vector<std::string>& architectures,
                                       const std::vector<std::string>& sets);

// The comparison table: one row per metric, one column per architecture.
std::string compare_table(const std::vector<CompareColumn>& columns, TableFormat format);
nlohmann::json compare_json(const std::vector<CompareColumn>& columns);

}  // namespace cnc::sim
