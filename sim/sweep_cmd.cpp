#include "sweep_cmd.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <fmt/format.h>

#include "common/bad_input.hpp"
#include "output/output_file.hpp"
#include "scenario/scenario.hpp"
#include "sweep/sweep_check.hpp"
#include "sweep/sweep_results.hpp"
#include "sweep/sweep_run.hpp"
#include "sweep/sweep_search.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as a shell reports a command stopped by Ctrl-C

}  // namespace

int cmd_sweep(const std::string& file, const std::string& out_dir, std::size_t jobs) {
    SweepSpec spec = read_sweep_file(file);
    const CompareInput input{spec.input, [&spec](const std::vector<std::string>& overrides) {
                                 return spec.job ? load_job_run({spec.input, spec.machine, ""}, overrides)
                                                 : load_scenario(spec.input, overrides);
                             }};
    Scenario base;
    try {
        base = input.load({});
    } catch (const BadInput& e) {
        throw BadInput(spec.where(spec.input_line, spec.job ? "job" : "scenario"), e.what());
    }
    const std::vector<std::string> architectures = point_architectures(spec, base.architecture);
    std::vector<SweepPoint> points =
        spec.search ? first_search_points(spec, architectures) : expand_points(spec, base.architecture);
    check_sweep(spec, points, input);
    check_output_dir(out_dir, "--out");
    fs::create_directories(out_dir);

    SweepRunOptions options{fs::read_symlink("/proc/self/exe").string(), {spec.input}, out_dir, jobs};
    if (!spec.machine.empty()) options.input.insert(options.input.end(), {"--machine", spec.machine});
    if (options.jobs == 0) options.jobs = std::max(1L, sysconf(_SC_NPROCESSORS_ONLN));
    std::vector<std::string> checked;  // the architectures whose first report the metrics were checked on
    const auto after_point = [&](const SweepPoint& p) {
        if (std::find(checked.begin(), checked.end(), p.architecture) != checked.end()) return;
        const fs::path report = point_report(out_dir, p);
        std::ifstream in(report);
        check_metrics(spec, nlohmann::json::parse(in, nullptr, false), p.architecture, report.string());
        checked.push_back(p.architecture);
    };
    SweepRunOutcome outcome;
    std::vector<SearchResult> found;
    if (spec.search) {
        points.clear();
        found = run_search(spec, architectures, options, points, outcome, after_point);
        // Each architecture's values together, in the order the search tried them.
        std::sort(points.begin(), points.end(),
                  [](const SweepPoint& a, const SweepPoint& b) { return a.index < b.index; });
    } else {
        outcome = run_points(points, options, after_point);
    }
    if (outcome.interrupted) {
        std::cerr << fmt::format(FMT_STRING("cncsim sweep: interrupted with {} of {} points done; the same command "
                                            "resumes it"),
                                 outcome.already_done + outcome.ran, points.size())
                  << std::endl;
        return kExitInterrupted;
    }
    const std::vector<SweepRow> rows = collect_rows(spec, points, out_dir);
    const fs::path dir(out_dir);
    write_output_file((dir / "results.csv").string(), "--out", results_csv(spec, rows));
    write_output_file((dir / "results.json").string(), "--out", results_json(spec, rows).dump(1) + "\n");
    write_output_file((dir / "summary.md").string(), "--out", summary_md(spec, rows));
    if (spec.search) {
        const std::string md = search_md(spec, found);
        write_output_file((dir / "search.md").string(), "--out", md);
        write_output_file((dir / "search.json").string(), "--out", search_json(spec, found).dump(1) + "\n");
        std::cout << md;
    }
    try {
        const std::size_t plots = write_sweep_plots(spec, rows, dir);
        std::cerr << "cncsim sweep: " << plots << " plots in " << (dir / "plots").string() << std::endl;
    } catch (const std::runtime_error& e) {
        std::cerr << "cncsim sweep: no plots: " << e.what() << std::endl;
    }
    std::cerr << "cncsim sweep: " << (dir / "summary.md").string() << ", results.csv, results.json"
              << (spec.search ? ", search.md, search.json" : "") << std::endl;
    return outcome.failed == 0 ? 0 : 1;
}

}  // namespace cnc::sim
