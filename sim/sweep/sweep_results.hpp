// A sweep's results from its points' records and reports: results.csv and results.json (a row per point),
// summary.md (per study, metric, architecture and value: the statistics across the seeds) and the plots (each
// metric against the study's first swept key, a line per architecture in compare's colours).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/sweep_file.hpp"
#include "sweep/sweep_points.hpp"

namespace cnc::sim {

struct SweepRow {
    const SweepPoint* point = nullptr;
    PointRecord record;
    std::vector<std::optional<double>> metrics;  // per SweepSpec::metrics; none for a failed point
};

// The metric's pointer in an architecture's report: "{arch}" replaced by its name.
nlohmann::json::json_pointer metric_pointer(const SweepMetric& metric, const std::string& architecture);

// BadInput naming the sweep file's line of the first metric `report` (of `architecture`, read from `report_file`)
// does not hold, with the keys its deepest part that exists holds.
void check_metrics(const SweepSpec& spec, const nlohmann::json& report, const std::string& architecture,
                   const std::string& report_file);

// The row of each point from its record and report (every point must have a record).
std::vector<SweepRow> collect_rows(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                                   const std::filesystem::path& out_dir);

std::string results_csv(const SweepSpec& spec, const std::vector<SweepRow>& rows);
nlohmann::json results_json(const SweepSpec& spec, const std::vector<SweepRow>& rows);
std::string summary_md(const SweepSpec& spec, const std::vector<SweepRow>& rows);

// Draws the plots into out_dir/plots (gnuplot); returns how many. Throws std::runtime_error when gnuplot fails.
std::size_t write_sweep_plots(const SweepSpec& spec, const std::vector<SweepRow>& rows,
                              const std::filesystem::path& out_dir);

}  // namespace cnc::sim
