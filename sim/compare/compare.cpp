#include "compare/compare.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "architectures/catalog.hpp"
#include "compare/spawn.hpp"
#include "metrics/report/zero_notes.hpp"
#include "output/table_cells.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

// A row's value as printed: fixed decimals, with its sign always shown for a deviation that goes either way.
struct Decimals {
    int places;
    bool sign = false;
};
constexpr Decimals fixed(int places) {
    return {places, false};
}
constexpr Decimals signed_fixed(int places) {
    return {places, true};
}

std::string shown(double v, Decimals d) {
    return d.sign ? fmt::format(FMT_STRING("{:+.{}f}"), v, d.places) : fmt::format(FMT_STRING("{:.{}f}"), v, d.places);
}

struct Row {
    const char* label;
    const char* pointer;           // JSON pointer into a run report
    Decimals decimals;             // of the value as printed
    bool setting = false;          // what the run was given (shown for a failed run too), not a result
    bool in_arch_section = false;  // the pointer is into the architecture's own section (report[arch])
    // Followed, with a baseline run, by the column's value minus the baseline's: what the controller adds to the
    // machine's own figure.
    bool over_baseline = false;
    // Measured against the architecture's own commanded motion (uniform rates without a planner, the planned
    // trajectory with one: docs/metrics.md, Terms), so the columns' figures are not the same quantity and none is
    // marked best.
    bool own_reference = false;
    // Shown only when a column's report has the figure: the figures of a run with faults (docs/faults.md).
    bool when_present = false;
};

constexpr Row against_own_command(Row row) {
    row.own_reference = true;
    return row;
}

constexpr Row with_faults(Row row) {
    row.in_arch_section = true;
    row.when_present = true;
    return row;
}

// The machine each run used, then the headline numbers of docs/metrics.md in the order a reader compares them.
constexpr Row kRows[] = {
    {"machine: X steps/mm", "/scenario/machine/x/steps_per_mm", fixed(4), true},
    {"machine: X microsteps", "/scenario/machine/x/microsteps", fixed(0), true},
    {"machine: X full steps/mm", "/scenario/machine/x/full_steps_per_mm", fixed(4), true},
    {"machine: X velocity max [mm/s]", "/scenario/machine/x/max_velocity_mm_per_s", fixed(1), true},
    {"machine: X accel max [mm/s^2]", "/scenario/machine/x/max_accel_mm_per_s2", fixed(0), true},
    {"machine: X jerk max [mm/s^3]", "/scenario/machine/x/max_jerk_mm_per_s3", fixed(0), true},
    {"machine: Y steps/mm", "/scenario/machine/y/steps_per_mm", fixed(4), true},
    {"machine: Y microsteps", "/scenario/machine/y/microsteps", fixed(0), true},
    {"machine: Y full steps/mm", "/scenario/machine/y/full_steps_per_mm", fixed(4), true},
    {"machine: Y velocity max [mm/s]", "/scenario/machine/y/max_velocity_mm_per_s", fixed(1), true},
    {"machine: Y accel max [mm/s^2]", "/scenario/machine/y/max_accel_mm_per_s2", fixed(0), true},
    {"machine: Y jerk max [mm/s^3]", "/scenario/machine/y/max_jerk_mm_per_s3", fixed(0), true},
    {"machine: rapid speed [mm/min]", "/scenario/machine/rapid_feed_mm_per_min", fixed(1), true},
    {"job time [s]", "/metrics/job/job_time_s", fixed(4)},
    {"motion time [s]", "/metrics/job/motion_time_s", fixed(4)},
    // Between the programmed moves, inside them (between an arc's chords, a long line's commands), and the sum.
    {"dead time between moves [ms]", "/metrics/job/dead_total_ms", fixed(3)},
    {"dead time inside moves [ms]", "/metrics/job/dead_inside_total_ms", fixed(3)},
    {"dead time total [ms]", "/metrics/job/dead_all_total_ms", fixed(3)},
    {"dead time mean between moves [ms]", "/metrics/job/dead_mean_ms", fixed(3)},
    // The clock each run's logic had (none for an architecture without one: docs/metrics.md "Clocks").
    {"clock offset [ppm]", "/clock/offset_ppm", signed_fixed(3), true},
    {"clock jitter rms [ps]", "/clock/jitter_rms_ps", fixed(1), true},
    {"TIE max [ns]", "/metrics/pulse/tie_max_ns", fixed(3)},
    {"period jitter p-p max [ns]", "/metrics/pulse/jitter_pp_max_ns", fixed(3)},
    against_own_command({"rate error worst [%]", "/metrics/pulse/rate_error_worst_pct", signed_fixed(4)}),
    against_own_command({"sync error max [us]", "/metrics/pulse/sync_max_us", fixed(1)}),
    against_own_command({"feed error max [%]", "/metrics/feed/feed_error_max_abs_pct", fixed(4)}),
    {"contour error max [um]", "/metrics/path/contour_max_um", fixed(2), false, false, true},
    {"contour error rms [um]", "/metrics/path/contour_rms_um", fixed(2)},
    against_own_command({"following error max [um]", "/metrics/path/following_max_um", fixed(2)}),
    {"job end error [um]", "/metrics/path/job_end_um", fixed(2)},
    // The dynamic mechanics' (none with the ideal carriage): 90 electrical degrees is pull-out, a slip 4 full steps.
    {"lost full steps X", "/mechanics/x/lost_full_steps", fixed(0), false, true},
    {"lost full steps Y", "/mechanics/y/lost_full_steps", fixed(0), false, true},
    {"peak load angle X [el. deg]", "/mechanics/x/peak_load_angle_electrical_deg", fixed(1), false, true},
    {"peak load angle Y [el. deg]", "/mechanics/y/peak_load_angle_electrical_deg", fixed(1), false, true},
    {"DRV8825 violations", "/metrics/pulse/driver_violations", fixed(0)},
    {"laser dwell [ms]", "/metrics/laser/dwell_ms", fixed(3)},
    {"laser on in rapids [ms]", "/metrics/laser/on_in_rapid_ms", fixed(3)},
    // What the faults on the link did: the commands (packets, transfers, frames) the controller ran changed without
    // anything noticing, and those the host sent again.
    with_faults({"link: commands run changed unnoticed", "/faults/commands_run_changed", fixed(0)}),
    with_faults({"link: commands sent again", "/faults/retransmitted", fixed(0)}),
};

nlohmann::json::json_pointer where(const Row& row, const CompareColumn& c) {
    return nlohmann::json::json_pointer(row.in_arch_section ? "/" + c.architecture + row.pointer : row.pointer);
}

// The row's figure of a run, when its report has one.
std::optional<double> figure(const CompareColumn& c, const Row& row) {
    return report_number(c.report, where(row, c));
}

// The rows the comparison shows, in kRows' order.
std::vector<Row> shown_rows(const Comparison& comparison) {
    std::vector<Row> rows;
    for (const Row& row : kRows) {
        const auto has = [&row](const CompareColumn& c) { return figure(c, row).has_value(); };
        if (!row.when_present || std::any_of(comparison.columns.begin(), comparison.columns.end(), has))
            rows.push_back(row);
    }
    return rows;
}

// A failed run's figures cover only what ran before it stopped: never shown as a result (its JSON keeps them
// apart as partial_metrics).
std::string cell(const CompareColumn& c, const Row& row) {
    const std::optional<double> v = figure(c, row);
    if (!v || (c.exit_code != 0 && !row.setting)) return "-";
    return shown(*v, row.decimals);
}

// The column's figure minus the baseline's, when both runs have it.
std::optional<double> over(const CompareColumn& c, const Row& row, const CompareColumn& baseline) {
    const std::optional<double> v = figure(c, row);
    const std::optional<double> b = figure(baseline, row);
    if (!v || !b) return std::nullopt;
    return *v - *b;
}

std::string over_cell(const CompareColumn& c, const Row& row, const CompareColumn& baseline) {
    const std::optional<double> d = over(c, row, baseline);
    if (!d || c.exit_code != 0 || baseline.exit_code != 0) return "-";
    return shown(*d, row.decimals);
}

// "contour error max over ideal [um]": the row's label with the baseline named before its unit.
std::string over_label(const Row& row, const std::string& baseline) {
    const std::string label = row.label;
    const auto unit = label.rfind(" [");
    return label.substr(0, unit) + " over " + baseline + (unit == std::string::npos ? "" : label.substr(unit));
}

// Its key in a column's JSON metrics: "metrics/path/contour_max_um" -> "metrics/path/contour_max_over_ideal_um".
std::string over_key(const Row& row, const std::string& baseline) {
    const std::string key = row.pointer + 1;
    const auto unit = key.rfind('_');
    return key.substr(0, unit) + "_over_" + baseline + (unit == std::string::npos ? "" : key.substr(unit));
}

// The smallest magnitude as printed, when at least two cells have a value and they are not all the same.
std::vector<bool> best_cells(const std::vector<std::string>& cells) {
    std::vector<double> v(cells.size(), -1.0);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i] != "-") v[i] = std::fabs(std::stod(cells[i]));
    }
    std::vector<bool> best(cells.size(), false);
    const auto valued = [](double x) { return x >= 0.0; };
    if (std::count_if(v.begin(), v.end(), valued) < 2) return best;
    double lo = 1e300;
    double hi = -1.0;
    for (const double x : v) {
        if (!valued(x)) continue;
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    }
    if (lo == hi) return best;
    for (std::size_t i = 0; i < v.size(); ++i) best[i] = valued(v[i]) && v[i] == lo;
    return best;
}

std::string join(const std::vector<std::string>& parts, const char* sep) {
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? sep : "") + parts[i];
    return out;
}

std::vector<std::string> child_args(const std::string& self_exe, const std::vector<std::string>& input,
                                    const CompareColumn& c, const std::vector<std::string>& sets,
                                    const fs::path& report, const std::string& out_dir) {
    // Progress as whole lines (a line per 10 % of the child's estimate), named by architecture.
    std::vector<std::string> args = {self_exe, "run"};
    args.insert(args.end(), input.begin(), input.end());
    args.insert(args.end(), {"--progress", "log", "--set", "scenario.architecture=" + c.architecture});
    // The variant's after the command's own: a key both set takes the variant's value.
    for (const std::vector<std::string>* list : {&sets, &c.variant_sets}) {
        for (const std::string& s : *list) {
            args.push_back("--set");
            args.push_back(s);
        }
    }
    args.push_back("--report");
    args.push_back(report.string());
    if (!out_dir.empty()) {
        args.push_back("--vcd");
        args.push_back((fs::path(out_dir) / (c.file_stem() + ".vcd")).string());
        args.push_back("--plot-data");
        args.push_back((fs::path(out_dir) / "data" / c.file_stem()).string());
    }
    return args;
}

}  // namespace

std::optional<double> report_number(const nlohmann::json& report, const nlohmann::json::json_pointer& pointer) {
    if (!report.is_object() || !report.contains(pointer) || !report.at(pointer).is_number()) return std::nullopt;
    return report.at(pointer).get<double>();
}

std::string CompareColumn::label() const {
    return variant.empty() ? architecture : architecture + ": " + variant;
}

std::string CompareColumn::file_stem() const {
    return variant.empty() ? architecture : architecture + "." + variant;
}

std::string status(const CompareColumn& c) {
    if (c.exit_code == 0) return "ok";
    return c.exit_code == 2 ? "bad input" : "failed";
}

Comparison run_compare(const std::string& self_exe, const std::vector<std::string>& input,
                       const std::vector<CompareColumn>& asked, const std::vector<std::string>& sets,
                       const std::string& out_dir, bool with_baseline) {
    // The baseline runs too when it is not asked for as the scenario has it; its report alone, in the temporary
    // folder.
    std::vector<CompareColumn> columns = asked;
    const Architecture* baseline = baseline_architecture();
    const bool hidden_baseline =
        with_baseline && baseline != nullptr && std::none_of(asked.begin(), asked.end(), [&](const CompareColumn& c) {
            return c.architecture == baseline->name() && c.variant.empty();
        });
    if (hidden_baseline) {
        columns.emplace_back();
        columns.back().architecture = baseline->name();
    }
    std::string dir_template = (fs::temp_directory_path() / "cncsim-compare-XXXXXX").string();
    if (mkdtemp(dir_template.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder");
    const fs::path temp_dir = dir_template;
    const auto with_outputs = [&](std::size_t k) { return !out_dir.empty() && k < asked.size(); };
    const auto report_dir = [&](std::size_t k) { return with_outputs(k) ? fs::path(out_dir) : temp_dir; };
    std::map<pid_t, std::size_t> running;
    std::vector<std::chrono::steady_clock::time_point> started(columns.size());
    const std::size_t cores = std::max(1L, sysconf(_SC_NPROCESSORS_ONLN));
    std::size_t next = 0;
    std::size_t done = 0;
    while (done < columns.size()) {
        while (next < columns.size() && running.size() < cores) {
            const CompareColumn& c = columns[next];
            std::cerr << "cncsim compare: " << c.label() << (next < asked.size() ? "" : " (baseline)") << " running"
                      << std::endl;
            started[next] = std::chrono::steady_clock::now();
            running[spawn_child(child_args(self_exe, input, c, sets, report_dir(next) / (c.file_stem() + ".json"),
                                           with_outputs(next) ? out_dir : ""))] = next;
            ++next;
        }
        int exit_code = 0;
        const pid_t pid = wait_any_child(exit_code);
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        const std::size_t k = it->second;
        CompareColumn& c = columns[k];
        running.erase(it);
        ++done;
        c.exit_code = exit_code;
        c.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started[k]).count();
        std::ifstream in(report_dir(k) / (c.file_stem() + ".json"));
        if (in) c.report = nlohmann::json::parse(in, nullptr, false);
        if (c.report.is_discarded()) c.report = nullptr;
        std::string ratio;
        if (c.exit_code == 0 && c.report.contains(nlohmann::json::json_pointer("/metrics/job/job_time_s"))) {
            const double sim_s = c.report["metrics"]["job"]["job_time_s"].get<double>();
            ratio = fmt::format(FMT_STRING(" ({:.3f} s simulated, {:.1f}x real time)"), sim_s, sim_s / c.wall_s);
        }
        std::cerr << "cncsim compare: " << c.label() << " " << status(c)
                  << fmt::format(FMT_STRING(" after {:.1f} s"), c.wall_s) << ratio << " [" << done << '/'
                  << columns.size() << " done]" << std::endl;
    }
    fs::remove_all(temp_dir);
    Comparison out;
    if (hidden_baseline) {
        out.baseline = std::move(columns.back());
        columns.pop_back();
    }
    out.columns = std::move(columns);
    return out;
}

const CompareColumn* Comparison::baseline_column() const {
    if (baseline) return &*baseline;
    const Architecture* b = baseline_architecture();
    for (const CompareColumn& c : columns) {
        if (b != nullptr && c.architecture == b->name() && c.variant.empty()) return &c;
    }
    return nullptr;
}

std::string not_compared_note() {
    std::vector<std::string> labels;
    for (const Row& row : kRows) {
        if (row.own_reference) labels.emplace_back(row.label);
    }
    return "No best is marked on " + join(labels, ", ") +
           ": each architecture's is measured against its own commanded motion (uniform rates without a planner, "
           "the planned trajectory with one), so the figures are not the same quantity (docs/metrics.md).";
}

std::vector<std::string> zero_notes(const Comparison& comparison) {
    std::vector<std::string> notes;
    for (const CompareColumn& c : comparison.columns) {
        if (c.report.is_null() || c.exit_code != 0) continue;
        for (const std::string& n : metrics::zero_by_construction(c.report)) notes.push_back(c.label() + ": " + n);
    }
    return notes;
}

std::vector<TableRow> table_rows(const Comparison& comparison) {
    const std::vector<CompareColumn>& columns = comparison.columns;
    const CompareColumn* baseline = comparison.baseline_column();
    std::vector<TableRow> rows;
    TableRow st{"status", {}, std::vector<bool>(columns.size(), false)};
    for (const CompareColumn& c : columns) st.cells.push_back(status(c));
    rows.push_back(st);
    for (const Row& row : shown_rows(comparison)) {
        // A setting (the machine, the clock part) is what the run was given, not a result: never a best.
        TableRow r{row.label, {}, {}, !row.own_reference && !row.setting};
        for (const CompareColumn& c : columns) r.cells.push_back(cell(c, row));
        r.best = r.comparable ? best_cells(r.cells) : std::vector<bool>(r.cells.size(), false);
        rows.push_back(r);
        if (!row.over_baseline || baseline == nullptr) continue;
        TableRow o{over_label(row, baseline->architecture), {}, {}};
        for (const CompareColumn& c : columns) o.cells.push_back(over_cell(c, row, *baseline));
        o.best = best_cells(o.cells);
        rows.push_back(o);
    }
    return rows;
}

std::optional<TableRow> sets_row(const Comparison& comparison) {
    const std::vector<CompareColumn>& columns = comparison.columns;
    const auto variant = [](const CompareColumn& c) { return !c.variant.empty(); };
    if (std::none_of(columns.begin(), columns.end(), variant)) return std::nullopt;
    TableRow r{"variant sets", {}, std::vector<bool>(columns.size(), false), false};
    for (const CompareColumn& c : columns) r.cells.push_back(c.variant_sets.empty() ? "-" : join(c.variant_sets, ", "));
    return r;
}

nlohmann::json compare_json(const Comparison& comparison) {
    const std::vector<CompareColumn>& columns = comparison.columns;
    const CompareColumn* baseline = comparison.baseline_column();
    // Each table row's key, in the order of table_rows (after the status).
    std::vector<std::string> keys;
    const std::vector<Row> shown = shown_rows(comparison);
    for (const Row& row : shown) {
        keys.emplace_back(row.pointer + 1);
        if (row.over_baseline && baseline != nullptr) keys.push_back(over_key(row, baseline->architecture));
    }
    nlohmann::json out = nlohmann::json::array();
    const std::vector<TableRow> rows = table_rows(comparison);
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const CompareColumn& c = columns[k];
        nlohmann::json best = nlohmann::json::array();
        for (std::size_t r = 1; r < rows.size(); ++r) {  // rows[0] is the status
            if (rows[r].best[k]) best.push_back(keys[r - 1]);
        }
        nlohmann::json metrics = nlohmann::json::object();
        for (const Row& row : shown) {
            if (row.setting) continue;
            const nlohmann::json::json_pointer ptr = where(row, c);
            metrics[row.pointer + 1] =
                !c.report.is_null() && c.report.contains(ptr) ? c.report.at(ptr) : nlohmann::json(nullptr);
            if (!row.over_baseline || baseline == nullptr) continue;
            const std::optional<double> d = over(c, row, *baseline);
            metrics[over_key(row, baseline->architecture)] = d ? nlohmann::json(*d) : nlohmann::json(nullptr);
        }
        nlohmann::json column = {
            {"architecture", c.architecture},
            {"label", c.label()},
            {"variant", c.variant.empty() ? nlohmann::json(nullptr) : nlohmann::json(c.variant)},
            {"variant_sets", c.variant_sets},
            {"status", status(c)},
            {"exit_code", c.exit_code},
            {"machine", c.report.is_null()
                            ? nlohmann::json(nullptr)
                            : c.report.value("scenario", nlohmann::json::object()).value("machine", nlohmann::json())},
            {"clock", c.report.is_null() ? nlohmann::json(nullptr) : c.report.value("clock", nlohmann::json())},
            {"warnings",
             c.report.is_null() ? nlohmann::json::array() : c.report.value("warnings", nlohmann::json::array())},
            {"best", best}};
        if (c.exit_code == 0) {
            column["metrics"] = metrics;
        } else {
            column["metrics"] = nullptr;
            column["partial_metrics"] = metrics;
            column["failure"] =
                c.report.is_null() ? nlohmann::json(nullptr) : c.report.value("failure", nlohmann::json());
        }
        out.push_back(std::move(column));
    }
    return out;
}

std::string compare_table(const Comparison& comparison, TableFormat format_kind) {
    if (format_kind == TableFormat::Json) return compare_json(comparison).dump(2) + "\n";
    const std::vector<CompareColumn>& columns = comparison.columns;
    std::vector<std::string> head = {"metric"};
    for (const CompareColumn& c : columns) head.push_back(c.label());
    std::vector<std::vector<std::string>> rows = {head};
    const bool md = format_kind == TableFormat::Markdown;
    std::ostringstream os;
    if (format_kind == TableFormat::Csv) {
        head.push_back("best");
        rows = {head};
    }
    std::vector<TableRow> table = table_rows(comparison);
    // A row in a CSV file, which is read by program; under the table for a reader, where a variant's sets would
    // widen its column past the screen.
    const std::optional<TableRow> sets = sets_row(comparison);
    if (sets && format_kind == TableFormat::Csv) table.insert(table.begin() + 1, *sets);
    for (const TableRow& tr : table) {
        std::vector<std::string> r = {tr.label};
        std::vector<std::string> best_names;
        for (std::size_t i = 0; i < tr.cells.size(); ++i) {
            if (tr.best[i]) best_names.push_back(columns[i].label());
            if (format_kind == TableFormat::Csv) {
                r.push_back(tr.cells[i]);
            } else if (md) {
                r.push_back(tr.best[i] ? "**" + tr.cells[i] + "**" : md_cell(tr.cells[i]));
            } else {
                r.push_back(tr.cells[i] + (tr.best[i] ? "*" : " "));
            }
        }
        if (format_kind == TableFormat::Csv) r.push_back(join(best_names, " "));
        rows.push_back(r);
    }
    if (format_kind == TableFormat::Csv) {
        for (const auto& r : rows) {
            // A variant's sets hold quotes ("crc16"): every cell quoted.
            for (std::size_t i = 0; i < r.size(); ++i) os << (i ? "," : "") << csv_quoted(r[i]);
            os << '\n';
        }
        return os.str();
    }
    std::vector<std::size_t> width(rows.front().size(), 0);
    for (const auto& r : rows) {
        for (std::size_t i = 0; i < r.size(); ++i) width[i] = std::max(width[i], r[i].size());
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const auto& r = rows[k];
        for (std::size_t i = 0; i < r.size(); ++i) {
            const std::string pad(width[i] - r[i].size(), ' ');
            os << (md ? "| " : (i ? "  " : "")) << (i == 0 ? r[i] + pad : pad + r[i]) << (md ? " " : "");
        }
        os << (md ? "|\n" : "\n");
        if (k == 0) {
            for (std::size_t i = 0; i < r.size(); ++i) {
                os << (md ? "|" : (i ? "--" : "")) << std::string(width[i] + (md ? 2 : 0), '-');
            }
            os << (md ? "|\n" : "\n");
        }
    }
    if (!md) os << "* best of the row (smallest magnitude)\n";
    if (sets) {
        for (std::size_t i = 0; i < columns.size(); ++i) {
            const std::string what =
                sets->cells[i] == "-" ? "the scenario as it is" : "--set " + join(columns[i].variant_sets, " --set ");
            os << (md ? "- " : "") << (md ? "**" + columns[i].label() + "**" : columns[i].label()) << ": "
               << (md ? md_cell(what) : what) << '\n';
        }
    }
    os << not_compared_note() << '\n';
    for (const std::string& n : zero_notes(comparison)) os << n << '\n';
    return os.str();
}

}  // namespace cnc::sim
