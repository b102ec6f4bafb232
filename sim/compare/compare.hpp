// cncsim compare: one job on one machine through several architectures, side by side. Each
// architecture runs in its own child process (`cncsim run`), since SystemC allows one elaboration per process.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cnc::sim {

struct CompareColumn {
    std::string architecture;
    int exit_code = 0;      // of the child `cncsim run`: 0 ok, 1 run failed, 2 bad input
    nlohmann::json report;  // its JSON report (null when it wrote none)
    double wall_s = 0.0;    // the child's wall time
};

// The columns asked for, and the baseline architecture's run (Architecture::baseline) when it is not one of them:
// the rows that measure each column over it read it.
struct Comparison {
    std::vector<CompareColumn> columns;
    std::optional<CompareColumn> baseline;
    // The baseline's run, shown or not; null without one.
    [[nodiscard]] const CompareColumn* baseline_column() const;
};

enum class TableFormat { Text, Markdown, Csv, Json };

// Runs `self_exe run INPUT... --set scenario.architecture=A [--set ...] --report R` for each architecture (INPUT: the
// scenario, or the job and its --machine), and for the baseline architecture when it is not one of them and
// `with_baseline`, as many at once as the machine has cores. With `out_dir`,
// R is out_dir/A.json and each child also writes out_dir/A.vcd and its plot data in out_dir/data/A/ (the baseline,
// when it is not asked for, writes none of them); without, R is a temporary file.
Comparison run_compare(const std::string& self_exe, const std::vector<std::string>& input,
                       const std::vector<std::string>& architectures, const std::vector<std::string>& sets,
                       const std::string& out_dir = "", bool with_baseline = true);

// One metric row: its label (unit in brackets), a cell per column ("-" when the run has no such figure) and which
// cells hold the row's best value (the smallest magnitude among two or more that differ).
struct TableRow {
    std::string label;
    std::vector<std::string> cells;
    std::vector<bool> best;
    bool comparable = true;  // the columns' figures are the same quantity; otherwise no best is marked
};
// With a baseline run, each row marked Row::over_baseline is followed by the column's value minus the baseline's.
std::vector<TableRow> table_rows(const Comparison& comparison);
// Which rows are not marked best, and why: one sentence.
std::string not_compared_note();
// Per column, the figures that are 0 by construction and why, each line led by the column's architecture.
std::vector<std::string> zero_notes(const Comparison& comparison);
std::string status(const CompareColumn& c);

// The comparison table: one row per metric, one column per architecture; best values marked (text: a trailing
// `*`, Markdown: bold, CSV: a last column naming the best architectures, JSON: each column's `best` metrics).
std::string compare_table(const Comparison& comparison, TableFormat format);
nlohmann::json compare_json(const Comparison& comparison);

}  // namespace cnc::sim
