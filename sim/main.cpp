// cncsim: the command line. Exit codes: 0 ok, 1 run failed, 2 bad input.
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <systemc>

#include "architectures/catalog.hpp"
#include "cam_cmd.hpp"
#include "common/bad_input.hpp"
#include "compare/compare.hpp"
#include "compare/compare_check.hpp"
#include "compare/compare_outputs.hpp"
#include "init_cmd.hpp"
#include "metrics/metrics.hpp"
#include "metrics/pulse/commanded_rates.hpp"
#include "metrics/report/report.hpp"
#include "metrics/vcd/analyze_input.hpp"
#include "metrics/vcd/vcd_reader.hpp"
#include "motor_curve_cmd.hpp"
#include "output/gtkw_save.hpp"
#include "output/output_file.hpp"
#include "output/samples_csv.hpp"
#include "plots/run_plots.hpp"
#include "run/run.hpp"
#include "scenario/drawing_job.hpp"
#include "scenario/key_listing.hpp"
#include "scenario/scenario.hpp"
#include "sweep_cmd.hpp"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitRunFailed = 1;
constexpr int kExitBadInput = 2;

void write_json(const std::string& path, const nlohmann::json& j) {
    cnc::sim::write_output_file(path, "--report", cnc::metrics::report_text(j));
}

// What `run` and `compare` read: a scenario, or a job with the machine it runs on (scenario.hpp, input_kind).
struct Input {
    std::string file;
    std::string machine;  // --machine
    std::string arch;     // run --arch
    [[nodiscard]] bool job() const { return cnc::sim::input_kind(file) == cnc::sim::InputKind::Job; }
};

cnc::sim::Scenario load_scenario_or_job(const Input& in, const std::vector<std::string>& sets) {
    if (!in.arch.empty()) (void)cnc::sim::find_architecture(in.arch, "--arch " + in.arch);
    if (in.job()) return cnc::sim::load_job_run({in.file, in.machine, in.arch}, sets);
    if (!in.machine.empty()) {
        throw cnc::BadInput("--machine " + in.machine,
                            "goes with a job (cncsim run JOB.nc --machine MACHINE.toml); " + in.file +
                                " is a scenario, which names its machine file as scenario.machine");
    }
    std::vector<std::string> with_arch = sets;  // --arch first: a --set of the key still wins
    if (!in.arch.empty()) with_arch.insert(with_arch.begin(), "scenario.architecture=" + in.arch);
    return cnc::sim::load_scenario(in.file, with_arch);
}

// The scenario with its job ready to read: a DXF job's G-code written (drawing_job.hpp).
cnc::sim::Scenario load_input(const Input& in, const std::vector<std::string>& sets) {
    cnc::sim::Scenario s = load_scenario_or_job(in, sets);
    cnc::sim::write_drawing_job(s);
    return s;
}

int cmd_run(const Input& input, const std::vector<std::string>& sets, const std::string& vcd, const std::string& report,
            bool detail, const std::string& progress, const std::string& plots, const std::string& plot_data,
            const std::string& samples) {
    cnc::sim::Scenario s = load_input(input, sets);
    if (detail) s.detail = true;
    if (!vcd.empty()) s.vcd_path = vcd;
    if (!report.empty()) s.report_path = report;
    s.keep_run_input = !plots.empty() || !plot_data.empty() || !samples.empty();
    // Every output can be written before anything is simulated; the report is opened now and filled at the end.
    const std::string vcd_label = vcd.empty() ? s.file + ": trace.vcd" : "--vcd";
    const std::optional<std::string> gtkw = s.vcd_path.empty() ? std::nullopt : cnc::sim::gtkw_path(s.vcd_path);
    if (!s.vcd_path.empty()) cnc::sim::check_output_path(s.vcd_path, vcd_label);
    if (gtkw) cnc::sim::check_output_path(*gtkw, vcd_label + " (its gtkwave save file)");
    if (!plots.empty()) cnc::sim::check_output_dir(plots, "--plots");
    if (!plot_data.empty()) cnc::sim::check_output_dir(plot_data, "--plot-data");
    std::optional<cnc::sim::OutputFile> samples_file;
    if (!samples.empty()) samples_file.emplace(samples, "--samples");
    std::optional<cnc::sim::OutputFile> report_file;
    if (!s.report_path.empty()) {
        report_file.emplace(s.report_path, report.empty() ? s.file + ": trace.report" : "--report");
    }
    s.progress = progress == "off"       ? cnc::sim::ProgressStyle::Off
                 : progress == "log"     ? cnc::sim::ProgressStyle::Log
                 : isatty(STDERR_FILENO) ? cnc::sim::ProgressStyle::Terminal
                                         : cnc::sim::ProgressStyle::Log;
    const cnc::sim::RunOutcome out = cnc::sim::run_scenario(s);
    std::cout << out.summary;
    if (gtkw && out.arch.trace) {  // the VCD's view, written with it for a failed run too
        cnc::sim::write_output_file(*gtkw, vcd_label + " (its gtkwave save file)",
                                    cnc::sim::gtkw_text(s.vcd_path, *out.arch.trace, out.arch.first_move));
    }
    if (samples_file) {  // a trace of what ran, like the VCD: written for a failed run too
        cnc::sim::write_samples_csv(samples_file->stream(), out.arch.input.tool);
        samples_file->close();
    }
    if (report_file) {
        cnc::sim::write_report(report_file->stream(), out);
        report_file->close();
    }
    if (out.ok) cnc::sim::write_run_plots(out, s, plots, plot_data);  // a failed run's figures are no result
    if (!out.ok) {
        std::cerr << "cncsim: run failed: " << out.failure << '\n';
        return kExitRunFailed;
    }
    return kExitOk;
}

// The axes of `cncsim analyze`: the i-th --step with the i-th --dir and, if any are given, the i-th --enable.
std::vector<cnc::metrics::AxisSignalNames> analyze_axes(const std::vector<std::string>& steps,
                                                        const std::vector<std::string>& dirs,
                                                        const std::vector<std::string>& enables) {
    const std::string counts = " (" + std::to_string(steps.size()) + " --step, " + std::to_string(dirs.size()) +
                               " --dir, " + std::to_string(enables.size()) + " --enable)";
    if (dirs.size() != steps.size()) throw cnc::BadInput("--dir", "give one --dir per --step" + counts);
    if (!enables.empty() && enables.size() != steps.size()) {
        throw cnc::BadInput("--enable", "give one --enable per --step, or none" + counts);
    }
    std::vector<cnc::metrics::AxisSignalNames> axes;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        cnc::metrics::AxisSignalNames a{steps[i], dirs[i], "", cnc::metrics::EnableLevel::ActiveLow};
        if (!enables.empty()) {
            const cnc::metrics::EnableOption e = cnc::metrics::parse_enable_option(enables[i]);
            a.enable = e.name;
            a.enable_active = e.active;
        }
        axes.push_back(a);
    }
    return axes;
}

int cmd_analyze(const std::string& vcd_path, const std::vector<cnc::metrics::AxisSignalNames>& axes,
                double steps_per_mm, const std::string& commanded, const std::string& report) {
    // CLI11's PositiveNumber lets nan and inf through (nan <= 0 is false).
    if (!std::isfinite(steps_per_mm)) throw cnc::BadInput("--steps-per-mm", "must be a finite number > 0");
    if (!report.empty()) cnc::sim::check_output_path(report, "--report");
    std::ifstream in(vcd_path);
    if (!in) throw cnc::BadInput(vcd_path, "cannot open the VCD file");
    const cnc::metrics::VcdContents vcd = cnc::metrics::read_vcd(in, vcd_path);
    cnc::metrics::RunInput input = cnc::metrics::analyze_input(
        vcd, vcd_path, axes, steps_per_mm > 0 ? std::optional<double>(steps_per_mm) : std::nullopt);
    if (!commanded.empty()) {
        std::ifstream run_report(commanded);
        if (!run_report) throw cnc::BadInput(commanded, "cannot open the run's report (--commanded)");
        const nlohmann::json j = nlohmann::json::parse(run_report, nullptr, false);
        if (j.is_discarded()) throw cnc::BadInput(commanded, "not a JSON file (--commanded)");
        input.rate_segments = cnc::metrics::commanded_rates_from_report(j, commanded, axes.size());
    }
    const cnc::metrics::RunMetrics m = cnc::metrics::compute_metrics(input);
    std::cout << cnc::metrics::summary_table(m);
    if (!report.empty()) write_json(report, cnc::metrics::to_json(m));
    return kExitOk;
}

// The architectures `compare` can put side by side: those that run the scenario's job (`shown`: and that it shows
// unless asked: not the baseline, nor one that runs the user's own firmware).
std::string job_architectures(const std::string& separator = ", ", bool shown = false) {
    std::string text;
    for (const cnc::sim::Architecture* a : cnc::sim::architectures()) {
        if (a->job_use().runs_job && !(shown && (a->baseline() || !a->compared_by_default()))) {
            text += (text.empty() ? "" : separator) + a->name();
        }
    }
    return text;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The columns: each architecture of `list`, or with variants each variant on each architecture of `list` when
// --arch was given, else on the scenario's own.
std::vector<cnc::sim::CompareColumn> compare_columns(const std::vector<std::string>& list, bool arch_given,
                                                     const std::vector<cnc::sim::Variant>& variants,
                                                     const cnc::sim::Scenario& scenario) {
    std::vector<cnc::sim::CompareColumn> columns;
    if (variants.empty()) {
        for (const std::string& a : list) columns.push_back({a, 0, nullptr, 0.0, "", {}});
        return columns;
    }
    const std::vector<std::string> archs = arch_given ? list : std::vector<std::string>{scenario.architecture};
    for (const std::string& a : archs) {
        if (!cnc::sim::find_architecture(a, scenario.file + ": scenario.architecture").job_use().runs_job) {
            throw cnc::BadInput("--variant", "compares the variants of an architecture that runs a job (" +
                                                 job_architectures() + "); " + a + " does not");
        }
        for (const cnc::sim::Variant& v : variants) columns.push_back({a, 0, nullptr, 0.0, v.name, v.sets});
    }
    return columns;
}

int cmd_compare(const Input& input, const std::string& archs, bool arch_given,
                const std::vector<std::string>& variant_texts, const std::vector<std::string>& sets,
                const std::string& format_name, const std::string& report, const std::string& out_dir) {
    // Bad syntax is said before anything is read or run.
    std::vector<cnc::sim::Variant> variants;
    for (const std::string& text : variant_texts) variants.push_back(cnc::sim::parse_variant(text, "--variant"));
    cnc::sim::check_variant_names(variants, "--variant");
    std::vector<std::string> list;
    std::stringstream ss(archs);
    for (std::string a; std::getline(ss, a, ',');) {
        if (!cnc::sim::find_architecture(a, "--arch " + a).job_use().runs_job) {
            throw cnc::BadInput("--arch " + a, "compares the architectures that run a job (" + job_architectures() +
                                                   "); " + a + " does not");
        }
        list.push_back(a);
    }
    // Bad input is reported once, here, not once per child.
    const cnc::sim::Scenario scenario = load_input(input, sets);
    // The command's --variant replace the scenario's, as its --set replace its keys.
    std::string variants_from = "--variant";
    if (variants.empty() && !scenario.compare_variants.empty()) {
        variants = scenario.compare_variants;
        variants_from = input.file + ": compare.variants";
    }
    const std::vector<cnc::sim::CompareColumn> columns = compare_columns(list, arch_given, variants, scenario);
    const cnc::sim::CompareInput compare_input{
        input.file, [&input](const std::vector<std::string>& overrides) { return load_input(input, overrides); }};
    cnc::sim::check_compare_columns(compare_input, columns, sets, variants_from);
    if (!report.empty()) cnc::sim::check_output_path(report, "--report");
    const bool with_baseline = cnc::sim::baseline_runs(compare_input, columns, sets, std::cerr);
    if (!out_dir.empty()) {
        cnc::sim::check_output_dir(out_dir, "--out");
        std::filesystem::create_directories(out_dir);
    }
    const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
    std::vector<std::string> child_input = {input.file};
    if (!input.machine.empty()) child_input.insert(child_input.end(), {"--machine", input.machine});
    const cnc::sim::Comparison comparison =
        cnc::sim::run_compare(self, child_input, columns, sets, out_dir, with_baseline);
    const cnc::sim::TableFormat format = format_name == "markdown" ? cnc::sim::TableFormat::Markdown
                                         : format_name == "csv"    ? cnc::sim::TableFormat::Csv
                                         : format_name == "json"   ? cnc::sim::TableFormat::Json
                                                                   : cnc::sim::TableFormat::Text;
    std::cout << cnc::sim::compare_table(comparison, format);
    if (!report.empty()) write_json(report, cnc::sim::compare_json(comparison));
    if (!out_dir.empty()) {
        const bool job = input.job();
        const std::string shown = job ? input.machine : input.file;
        cnc::sim::write_compare_outputs(comparison, shown.empty() ? "the default machine" : shown,
                                        shown.empty() ? "" : read_text(shown), sets, scenario.job_path, out_dir);
    }
    int worst = kExitOk;
    for (const auto& c : comparison.columns)
        worst = std::max(worst, c.exit_code == kExitBadInput ? kExitBadInput : c.exit_code);
    return worst;
}

// The Markdown table (what docs/scenario-reference.md holds) to a pipe or a file, lines the terminal's width to a
// terminal.
int cmd_keys(const std::string& prefix) {
    std::vector<cnc::sim::KeyDoc> keys = cnc::sim::scenario_keys();
    if (!prefix.empty()) keys = cnc::sim::keys_with_prefix(keys, prefix);
    winsize size{};
    if (isatty(STDOUT_FILENO) && ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) {
        std::cout << cnc::sim::keys_text(keys, size.ws_col);
    } else {
        std::cout << cnc::sim::keys_markdown(keys);
    }
    return kExitOk;
}

// The summary and tables go to standard output: a full disk or a closed pipe there is a failed run, not exit 0.
int check_stdout(int code) {
    std::cout.flush();
    if (std::fflush(stdout) == 0 && !std::ferror(stdout) && std::cout.good()) return code;
    const int err = errno;
    std::cerr << "cncsim: run failed: writing standard output: " << std::strerror(err != 0 ? err : EIO) << '\n';
    return code == kExitOk ? kExitRunFailed : code;
}

int dispatch(int argc, char* argv[]) {
    CLI::App app{"cncsim: co-simulation of CNC / laser motion-control architectures"};
    app.require_subcommand(1);
    // The SystemC release too: results can differ between kernels (the project is built and tested on 2.3.4).
    app.set_version_flag("--version", std::string("cncsim ") + CNCSIM_VERSION + "\nSystemC " + sc_core::sc_release(),
                         "print the cncsim and SystemC versions and exit");

    std::string scenario, vcd, report, vcd_in, commanded, plots, plot_data, out_dir, samples, keys_prefix;
    std::string init_dir = ".";
    Input input;
    std::vector<std::string> sets, steps, dirs, enables;
    double steps_per_mm = 0.0;
    bool detail = false;

    const std::string input_help =
        "scenario (TOML), or a job (G-code: .nc, .ngc, .gcode, .tap, .txt, ...; a steps file; a DXF drawing) to run "
        "on --machine "
        "or the default machine (docs/usage.md says how the two are told apart)";
    const std::string machine_help =
        "with a job: the machine file (TOML: its [machine], [driver], [motor], [mechanics] tables; `cncsim init` "
        "writes one); default: every machine key's default, the seed 000 machine";
    CLI::App* run = app.add_subcommand("run", "run one scenario or job, print the summary, write the JSON report");
    run->add_option("file", input.file, input_help)->required();
    run->add_option("--machine", input.machine, machine_help);
    run->add_option(
        "--arch", input.arch,
        "architecture, instead of the scenario's (a job's default: " + cnc::sim::architecture_names().front() + ")");
    run->add_option("--set", sets, "override a scenario key: key=value (repeatable)");
    run->add_option("--vcd", vcd, "write a VCD trace to this file");
    run->add_option("--report", report, "write the JSON report to this file");
    run->add_option("--plots", plots, "write the run's plots (SVG, PNG) and their gnuplot data and scripts here");
    run->add_option("--samples", samples, "write the tool (carriage) samples to this CSV file: t_s,x_mm,y_mm");
    run->add_option("--plot-data", plot_data, "write only the plots' data files here (what compare asks of a run)");
    run->add_flag("--detail", detail, "the report also holds the per-period, per-packet and per-run logs");
    std::string progress = "auto";
    run->add_option("--progress", progress,
                    "progress on stderr for runs over a second of wall time: auto (a redrawn line on a terminal, "
                    "a line per 10 % otherwise), log (lines), off")
        ->check(CLI::IsMember({"auto", "log", "off"}))
        ->capture_default_str();

    CLI::App* analyze = app.add_subcommand("analyze", "pulse metrics of any VCD (simulated or captured)");
    analyze->add_option("vcd", vcd_in, "VCD file")->required();
    // One value per occurrence, repeated per axis (a list after one --step would swallow the file name).
    const auto one_per_axis = [](CLI::Option* o) {
        o->expected(1)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    };
    one_per_axis(analyze->add_option("--step", steps, "STEP signal name; repeat for more axes")->required());
    one_per_axis(analyze->add_option("--dir", dirs, "DIR signal name, one per --step")->required());
    one_per_axis(analyze->add_option("--enable", enables,
                                     "NAME[:active-high]: the driver's enable, one per --step; STEP edges while "
                                     "disabled do not count (active low, as the DRV8825's nENBL, unless "
                                     ":active-high)"));
    analyze->add_option("--steps-per-mm", steps_per_mm, "steps per mm, for distances and speeds")
        ->check(CLI::PositiveNumber);
    analyze->add_option("--commanded", commanded,
                        "REPORT.json of the run that wrote the VCD (`cncsim run --detail`): split pulse runs where "
                        "its command changed, not by period");
    analyze->add_option("--report", report, "write the JSON report to this file");

    std::string archs = job_architectures(",", true);
    std::string table_format = "text";
    std::vector<std::string> variant_texts;
    CLI::App* compare = app.add_subcommand(
        "compare", "the same job and machine on several architectures, or variants of one design, side by side");
    compare->add_option("file", input.file, input_help + "; its architecture is overridden")->required();
    compare->add_option("--machine", input.machine, machine_help);
    const cnc::sim::Architecture* baseline = cnc::sim::baseline_architecture();
    compare
        ->add_option("--arch", archs,
                     "architectures, comma-separated; with --variant, each variant runs on each of them (default "
                     "then: the scenario's architecture)" +
                         (baseline != nullptr ? "; " + baseline->name() +
                                                    ", the baseline of the rows measured over it, runs with every "
                                                    "comparison and is a column when named here"
                                              : std::string()))
        ->capture_default_str();
    CLI::Option* arch_option = compare->get_option("--arch");
    compare->add_option("--set", sets, "override a scenario key: key=value (repeatable)");
    // One variant per occurrence: its own commas are the variant's.
    compare
        ->add_option("--variant", variant_texts,
                     std::string("a column of its own: the scenario with these keys set after every --set, written ") +
                         cnc::sim::kVariantSyntax +
                         " (repeatable; instead of the scenario's compare.variants); on the scenario's architecture, "
                         "or on each of --arch")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    compare->add_option("--format", table_format, "table format")
        ->check(CLI::IsMember({"text", "markdown", "csv", "json"}))
        ->capture_default_str();
    compare->add_option("--report", report, "write the comparison as JSON to this file");
    compare->add_option("--out", out_dir,
                        "write here: index.html, the table (md, csv, json), the plots, each architecture's report "
                        "and VCD");

    std::string curve_axis = "x";
    std::string curve_csv;
    CLI::App* curve =
        app.add_subcommand("motor-curve", "pull-out torque, the load's torque and the pull-in rate of one axis");
    std::string curve_machine;
    curve->add_option("scenario", scenario, "scenario file (TOML), or --machine");
    curve->add_option("--machine", curve_machine,
                      "instead of a scenario: a machine file (TOML: its [machine], [driver], [motor], [mechanics] "
                      "tables; `cncsim init` writes one)");
    curve->add_option("--set", sets, "override a scenario key: key=value (repeatable)");
    curve->add_option("--axis", curve_axis, "axis")->check(CLI::IsMember({"x", "y"}))->capture_default_str();
    curve->add_option("--csv", curve_csv, "also write the table as CSV to this file");

    cnc::sim::CamCommand cam_cmd;
    CLI::App* cam =
        app.add_subcommand("cam", "a DXF drawing to G-code: the seeds' path orderings and ours (docs/cam.md)");
    cam->add_option("drawing", cam_cmd.drawing, "DXF drawing (ASCII): LINE, ARC, CIRCLE, LWPOLYLINE, POLYLINE")
        ->required();
    cam->add_option("--order", cam_cmd.order,
                    "selection, seed000, seed003 or optimized (sets cam.order; default "
                    "seed000)");
    cam->add_option("--out", cam_cmd.out, "write the G-code to this file");
    cam->add_flag("--compare-orders", cam_cmd.compare_orders, "every ordering side by side");
    cam->add_option("--arch", cam_cmd.arch,
                    "with --compare-orders: run each ordering's G-code on this architecture and show its job time");
    cam->add_option("--machine", cam_cmd.machine,
                    "machine file (TOML): its axes' travel bounds the drawing, its start position the first rapid");
    cam->add_flag("--skip-unread", cam_cmd.skip_unread,
                  "leave out entity types the CAM does not read, listing them (sets cam.skip_unread)");
    cam->add_option("--set", cam_cmd.sets, "override a scenario key: key=value (repeatable; cam.* keys: docs/cam.md)");
    cnc::sim::SweepCommand sweep_cmd;
    CLI::App* sweep = app.add_subcommand(
        "sweep", "a design-space study: every point of a sweep file as its own run, the results tabled and plotted");
    // Not required by CLI11: `cncsim sweep collect DIR` has neither; cmd_sweep asks for them otherwise.
    sweep->add_option("file", sweep_cmd.file, "sweep file (TOML, docs/sweeps.md)");
    sweep->add_option("--out", sweep_cmd.out_dir,
                      "write here: each point's report, results.csv, results.json, summary.md, plots/; a rerun "
                      "resumes from what is there (with --slurm: on storage every node shares)");
    sweep->add_option("--jobs", sweep_cmd.jobs, "points run at once (default: the cores; 1 with --point)")
        ->check(CLI::PositiveNumber);
    CLI::Option* slurm_flag =
        sweep->add_flag("--slurm", sweep_cmd.slurm, "submit the points to Slurm as a job array (sbatch) instead");
    sweep->add_option("--partition", sweep_cmd.partition, "with --slurm: the partition to run in")->needs(slurm_flag);
    sweep->add_option("--time", sweep_cmd.time, "with --slurm: each task's time limit (sbatch --time)")
        ->needs(slurm_flag);
    sweep
        ->add_option("--points-per-task", sweep_cmd.per_task,
                     "with --slurm: points each task runs (default 1, more to keep within 1000 tasks)")
        ->check(CLI::PositiveNumber);
    std::size_t sweep_task = 0;
    CLI::Option* sweep_point =
        sweep
            ->add_option("--point", sweep_task,
                         "run only job-array task K's points (K x points-per-task ..), as the local sweep does")
            ->excludes(slurm_flag);
    CLI::App* sweep_collect = sweep->add_subcommand(
        "collect", "a --slurm sweep's results from the points finished, and what is missing or failed");
    sweep_collect->add_option("dir", sweep_cmd.collect_dir, "the sweep's --out folder")->required();

    CLI::App* keys = app.add_subcommand(
        "keys", "print the scenario keys (type, default, range, meaning): Markdown, or lines to fit a terminal");
    keys->add_option("prefix", keys_prefix, "only the keys that start with it (machine.x, link, ...)");
    CLI::App* init = app.add_subcommand(
        "init", "write a scenario, its machine file and a small job to start from (overwrites nothing)");
    init->add_option("dir", init_dir, "folder to write them in (created if needed)")->capture_default_str();

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kExitOk : kExitBadInput;
    }
    try {
        if (run->parsed()) return cmd_run(input, sets, vcd, report, detail, progress, plots, plot_data, samples);
        if (compare->parsed()) {
            return cmd_compare(input, archs, arch_option->count() > 0, variant_texts, sets, table_format, report,
                               out_dir);
        }
        if (curve->parsed()) {
            return cnc::sim::cmd_motor_curve(scenario, curve_machine, sets, curve_axis, curve_csv, std::cout);
        }
        if (analyze->parsed()) {
            return cmd_analyze(vcd_in, analyze_axes(steps, dirs, enables), steps_per_mm, commanded, report);
        }
        if (init->parsed()) return cnc::sim::cmd_init(init_dir, std::cout);
        if (cam->parsed()) {
            return cnc::sim::cmd_cam(cam_cmd, std::filesystem::read_symlink("/proc/self/exe").string(), std::cout);
        }
        if (sweep->parsed()) {
            if (sweep_point->count() > 0) sweep_cmd.point = sweep_task;
            return cnc::sim::cmd_sweep(sweep_cmd);
        }
        return cmd_keys(keys_prefix);
    } catch (const cnc::BadInput& e) {
        std::cerr << "cncsim: " << e.what() << '\n';
        return kExitBadInput;
    } catch (const cnc::sim::OutputError& e) {
        std::cerr << "cncsim: run failed: " << e.what() << '\n';
        return kExitRunFailed;
    } catch (const cnc::metrics::MoveRecordsError& e) {
        std::cerr << "cncsim: run failed: " << e.what() << '\n';
        return kExitRunFailed;
    } catch (const std::exception& e) {
        std::cerr << "cncsim: internal error: " << e.what() << '\n';
        return kExitRunFailed;
    }
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    return check_stdout(dispatch(argc, argv));
}

// Our own main, so that the SystemC banner can be switched off before the kernel reads the environment.
int main(int argc, char* argv[]) {
    setenv("SC_COPYRIGHT_MESSAGE", "DISABLE", 0);
    return sc_core::sc_elab_and_sim(argc, argv);
}
