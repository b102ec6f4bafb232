// cncsim compare: one job on one machine through several architectures, or several variants of one design (the
// same architecture with other keys), side by side. Each column runs in its own child process (`cncsim run`), since
// SystemC allows one elaboration per process.
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
    std::string variant{};  // the variant's name (--variant, compare.variants); empty: the scenario as it is
    std::vector<std::string> variant_sets{};  // its key=value, applied after the command's own --set

    // Its name in headers, notes and plot titles: "ARCH", or "ARCH: VARIANT".
    [[nodiscard]] std::string label() const;
    // Its files' name in compare --out (report, VCD, data/...): "ARCH", or "ARCH.VARIANT".
    [[nodiscard]] std::string file_stem() const;
};

// The columns asked for, and the baseline architecture's run (Architecture::baseline) when it is not one of them:
// the rows that measure each column over it read it.
struct Comparison {
    std::vector<CompareColumn> columns;
    std::optional<CompareColumn> baseline;
    // The baseline's run, shown or not; null without one.
    [[nodiscard]] const CompareColumn* baseline_column() const;
};

// The number a run's report holds at `pointer` (a row's, a sweep's metric), when it holds one there.
std::optional<double> report_number(const nlohmann::json& report, const nlohmann::json::json_pointer& pointer);

enum class TableFormat { Text, Markdown, Csv, Json };

// Runs `self_exe run INPUT... --set scenario.architecture=A [--set ...] [--set VARIANT...] --report R` for each
// column asked for (its architecture and variant; INPUT: the scenario, or the job and its --machine), and for the
// baseline architecture when no column is it without a variant and `with_baseline`, as many at once as the machine
// has cores. With `out_dir`, R is out_dir/S.json (S: the column's file_stem) and each child also writes out_dir/S.vcd
// and its plot data in out_dir/data/S/ (the baseline, when it is not asked for, writes none of them); without, R is
// a temporary file.
Comparison run_compare(const std::string& self_exe, const std::vector<std::string>& input,
                       const std::vector<CompareColumn>& asked, const std::vector<std::string>& sets,
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
// Per column, the figures that are 0 by construction and why, each line led by the column's label.
std::vector<std::string> zero_notes(const Comparison& comparison);
std::string status(const CompareColumn& c);
// With variants, a row of each column's sets ("-": the scenario as it is): the CSV's second row; the other
// formats list them under the table, the page above it. Else none.
std::optional<TableRow> sets_row(const Comparison& comparison);

// The comparison table: one row per metric, one column per architecture or variant; best values marked (text: a
// trailing `*`, Markdown: bold, CSV: a last column naming the best columns, JSON: each column's `best` metrics).
std::string compare_table(const Comparison& comparison, TableFormat format);
nlohmann::json compare_json(const Comparison& comparison);

}  // namespace cnc::sim
