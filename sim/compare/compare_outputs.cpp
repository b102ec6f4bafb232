#include "compare/compare_outputs.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <fmt/format.h>

#include "compare/html_report.hpp"
#include "output/output_file.hpp"
#include "plots/plot_render.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

// The page shows a long job's head only.
constexpr std::size_t kJobLinesShown = 80;

// One OutputFile per page and table, like every output of the CLI: complete or not there.
void write_file(const fs::path& file, const std::string& text) {
    write_output_file(file.string(), "--out", text);
}

}  // namespace

void write_compare_outputs(const Comparison& comparison, const std::string& scenario_label,
                           const std::string& scenario_text, const std::vector<std::string>& sets,
                           const std::string& job_path, const std::string& out_dir) {
    const fs::path dir(out_dir);
    write_file(dir / "table.md", compare_table(comparison, TableFormat::Markdown));
    write_file(dir / "table.csv", compare_table(comparison, TableFormat::Csv));
    write_file(dir / "table.json", compare_table(comparison, TableFormat::Json));

    const auto start = std::chrono::steady_clock::now();
    std::vector<PlotSource> sources;
    const std::vector<std::string> colours = column_colours(comparison.columns);
    for (std::size_t k = 0; k < comparison.columns.size(); ++k) {
        const CompareColumn& c = comparison.columns[k];
        sources.push_back({c.file_stem(), c.label(), colours[k]});
    }
    const std::vector<Plot> plots = render_plots(load_plot_runs(dir, sources), dir);
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    std::cerr << "cncsim compare: " << plots.size()
              << fmt::format(FMT_STRING(" plots rendered in {:.2f} s"), wall.count()) << std::endl;

    HtmlJob job{scenario_label, scenario_text, sets, job_path, "", 0};
    std::ifstream in(job_path);
    for (std::string line; std::getline(in, line); ++job.job_lines) {
        if (job.job_lines < kJobLinesShown) job.job_text += line + "\n";
    }
    if (job.job_lines > kJobLinesShown)
        job.job_text += fmt::format(FMT_STRING("... ({} more lines)\n"), job.job_lines - kJobLinesShown);
    write_file(dir / "index.html", html_report(comparison, plots, job));
}

}  // namespace cnc::sim
