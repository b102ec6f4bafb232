#include "sweep_cmd.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <fmt/format.h>

#include "common/bad_input.hpp"
#include "compare/spawn.hpp"
#include "output/output_file.hpp"
#include "scenario/scenario.hpp"
#include "sweep/sweep_check.hpp"
#include "sweep/sweep_results.hpp"
#include "sweep/sweep_run.hpp"
#include "sweep/sweep_search.hpp"
#include "sweep/sweep_slurm.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as a shell reports a command stopped by Ctrl-C

// The sweep file read, its base scenario loaded and its points expanded (the first of each search), not yet checked.
struct Sweep {
    SweepSpec spec;
    CompareInput input;
    std::vector<std::string> architectures;
    std::vector<SweepPoint> points;
};

Sweep read_sweep(const std::string& file) {
    Sweep s{read_sweep_file(file), {}, {}, {}};
    s.input = {s.spec.input, [input = s.spec.input, machine = s.spec.machine,
                              job = s.spec.job](const std::vector<std::string>& overrides) {
                   return job ? load_job_run({input, machine, ""}, overrides) : load_scenario(input, overrides);
               }};
    Scenario base;
    try {
        base = s.input.load({});
    } catch (const BadInput& e) {
        throw BadInput(s.spec.where(s.spec.input_line, s.spec.job ? "job" : "scenario"), e.what());
    }
    s.architectures = point_architectures(s.spec, base.architecture);
    s.points = s.spec.search ? first_search_points(s.spec, s.architectures) : expand_points(s.spec, base.architecture);
    return s;
}

SweepRunOptions run_options(const SweepSpec& spec, const std::string& out_dir, std::size_t jobs) {
    SweepRunOptions options{fs::read_symlink("/proc/self/exe").string(), {spec.input}, out_dir, jobs};
    if (!spec.machine.empty()) options.input.insert(options.input.end(), {"--machine", spec.machine});
    return options;
}

// After each point that ran: the metrics checked on the first report of each architecture, as soon as it is there.
std::function<void(const SweepPoint&)> metric_check(const SweepSpec& spec, const std::string& out_dir) {
    return [&spec, out_dir, checked = std::vector<std::string>()](const SweepPoint& p) mutable {
        if (std::find(checked.begin(), checked.end(), p.architecture) != checked.end()) return;
        const fs::path report = point_report(out_dir, p);
        std::ifstream in(report);
        check_metrics(spec, nlohmann::json::parse(in, nullptr, false), p.architecture, report.string());
        checked.push_back(p.architecture);
    };
}

void write_results(const SweepSpec& spec, const std::vector<SweepPoint>& points, const fs::path& dir,
                   const std::vector<SearchResult>& found) {
    const std::vector<SweepRow> rows = collect_rows(spec, points, dir);
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
}

int interrupted(const SweepRunOutcome& outcome, std::size_t points) {
    std::cerr << fmt::format(FMT_STRING("cncsim sweep: interrupted with {} of {} points done; the same command "
                                        "resumes it"),
                             outcome.already_done + outcome.ran, points)
              << std::endl;
    return kExitInterrupted;
}

void no_search(const SweepSpec& spec, const std::string& option) {
    if (spec.search) {
        throw BadInput(spec.where(spec.search->line, "[search]"),
                       option +
                           ": a search tries its values one after another, each from the outcome of the last; "
                           "run it without " +
                           option);
    }
}

int run_local(Sweep& s, const SweepCommand& c) {
    check_sweep(s.spec, s.points, s.input);
    check_output_dir(c.out_dir, "--out");
    fs::create_directories(c.out_dir);
    const SweepRunOptions options =
        run_options(s.spec, c.out_dir, c.jobs != 0 ? c.jobs : std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
    SweepRunOutcome outcome;
    std::vector<SearchResult> found;
    if (s.spec.search) {
        s.points.clear();
        found = run_search(s.spec, s.architectures, options, s.points, outcome, metric_check(s.spec, c.out_dir));
        // Each architecture's values together, in the order the search tried them.
        std::sort(s.points.begin(), s.points.end(),
                  [](const SweepPoint& a, const SweepPoint& b) { return a.index < b.index; });
    } else {
        outcome = run_points(s.points, options, metric_check(s.spec, c.out_dir));
    }
    if (outcome.interrupted) return interrupted(outcome, s.points.size());
    write_results(s.spec, s.points, c.out_dir, found);
    return outcome.failed == 0 ? 0 : 1;
}

// `--point K`: task K's points, run as the local sweep runs them (their records and reports the same).
int run_task(Sweep& s, const SweepCommand& c) {
    no_search(s.spec, "--point");
    const std::size_t per_task = c.per_task != 0 ? c.per_task : 1;
    const std::size_t tasks = task_count(s.points.size(), per_task);
    if (*c.point >= tasks) {
        throw BadInput("--point", fmt::format(FMT_STRING("{}: {} has {} points, tasks 0 .. {} at {} a task"), *c.point,
                                              c.file, s.points.size(), tasks - 1, per_task));
    }
    const auto [first, last] = task_points(*c.point, s.points.size(), per_task);
    const std::vector<SweepPoint> mine(s.points.begin() + static_cast<std::ptrdiff_t>(first),
                                       s.points.begin() + static_cast<std::ptrdiff_t>(last));
    check_sweep(s.spec, mine, s.input);
    check_output_dir(c.out_dir, "--out");
    fs::create_directories(c.out_dir);
    const SweepRunOutcome outcome =
        run_points(mine, run_options(s.spec, c.out_dir, c.jobs != 0 ? c.jobs : 1), metric_check(s.spec, c.out_dir));
    if (outcome.interrupted) return interrupted(outcome, mine.size());
    return outcome.failed == 0 ? 0 : 1;
}

// The tasks holding a point of `ids` (ascending point indices).
std::vector<std::size_t> tasks_of(const std::vector<std::size_t>& ids, std::size_t per_task) {
    std::vector<std::size_t> tasks;
    for (const std::size_t i : ids) {
        if (tasks.empty() || tasks.back() != i / per_task) tasks.push_back(i / per_task);
    }
    return tasks;
}

std::vector<std::size_t> points_to_run(const std::vector<SweepPoint>& points, const fs::path& out_dir) {
    std::vector<std::size_t> ids;
    for (const SweepPoint& p : points) {
        if (!point_done(p, read_point_record(out_dir, p))) ids.push_back(p.index);
    }
    return ids;
}

// `--slurm`: the point list and the job-array script into OUT/slurm/, and the tasks with points to run submitted.
int submit(Sweep& s, const SweepCommand& c) {
    no_search(s.spec, "--slurm");
    check_sweep(s.spec, s.points, s.input);
    const std::size_t per_task = c.per_task != 0 ? c.per_task : default_points_per_task(s.points.size());
    if (task_count(s.points.size(), per_task) > kSlurmMaxTasks) {
        throw BadInput("--points-per-task",
                       fmt::format(FMT_STRING("{}: {} points make {} tasks, more than the {} a "
                                              "Slurm job array takes by default"),
                                   per_task, s.points.size(), task_count(s.points.size(), per_task), kSlurmMaxTasks));
    }
    check_output_dir(c.out_dir, "--out");
    const fs::path slurm_dir = fs::absolute(c.out_dir) / "slurm";
    fs::create_directories(slurm_dir);
    SlurmSubmission sub{c.file,
                        c.out_dir,
                        fs::current_path().string(),
                        fs::read_symlink("/proc/self/exe").string(),
                        per_task,
                        c.partition,
                        c.time,
                        {}};
    for (const SweepPoint& p : s.points) sub.point_sets.push_back(p.sets);
    write_output_file((slurm_dir / "sweep.json").string(), "--out", submission_json(sub).dump(1) + "\n");
    const fs::path script = slurm_dir / "sweep.sh";
    write_output_file(script.string(), "--out", job_script(sub, (slurm_dir / "task_%A_%a.log").string()));
    const std::vector<std::size_t> tasks = tasks_of(points_to_run(s.points, c.out_dir), per_task);
    if (tasks.empty()) {
        std::cerr << "cncsim sweep: every point is done; cncsim sweep collect " << shell_word(c.out_dir)
                  << " makes the results" << std::endl;
        return 0;
    }
    const std::vector<std::string> sbatch = {"sbatch", "--parsable", "--array=" + array_list(tasks), script.string()};
    const fs::path answer = slurm_dir / "sbatch.out";
    int code = 0;
    try {
        code = run_child(sbatch, "", answer.string());
    } catch (const std::runtime_error& e) {
        throw BadInput("--slurm", std::string(e.what()) + " (Slurm's sbatch must be on the PATH)");
    }
    if (code != 0) {
        throw BadInput("--slurm", fmt::format(FMT_STRING("sbatch refused the job array (exit {}, its message above); "
                                                         "the script is {}"),
                                              code, script.string()));
    }
    std::string job = read_text(answer);
    job.erase(job.find_last_not_of(" \n") + 1);
    std::cerr << fmt::format(FMT_STRING("cncsim sweep: {} points in {} tasks of {} submitted as Slurm job {} "
                                        "(sbatch --array={} {}); when they have run: cncsim sweep collect {}"),
                             s.points.size(), tasks.size(), per_task, job, array_list(tasks),
                             shell_word(script.string()), shell_word(c.out_dir))
              << std::endl;
    return 0;
}

// `cncsim sweep collect DIR`: the results of the points finished, and what is missing or failed with the lines that
// run just those again.
int collect(const std::string& dir) {
    const fs::path out = fs::absolute(dir);
    const fs::path list = out / "slurm" / "sweep.json";
    if (!fs::is_regular_file(list)) {
        throw BadInput(dir,
                       "not a sweep submitted with --slurm: it has no slurm/sweep.json (a sweep run here writes "
                       "its results itself)");
    }
    const std::optional<SlurmSubmission> sub = parse_submission(read_text(list));
    if (!sub) throw BadInput(list.string(), "not the point list of a sweep submitted with --slurm");
    std::error_code ec;
    fs::current_path(sub->cwd, ec);  // the sweep file, and the paths it names, as the tasks read them
    if (ec) throw BadInput(list.string(), "cwd \"" + sub->cwd + "\": " + ec.message());
    Sweep s = read_sweep(sub->sweep_file);
    for (std::size_t i = 0; i < std::max(s.points.size(), sub->point_sets.size()); ++i) {
        if (i < s.points.size() && i < sub->point_sets.size() && s.points[i].sets == sub->point_sets[i]) continue;
        throw BadInput(sub->sweep_file, fmt::format(FMT_STRING("changed since it was submitted ({} points then, {} "
                                                               "now; point {} differs): submit it again with --slurm"),
                                                    sub->point_sets.size(), s.points.size(), i));
    }
    std::vector<SweepPoint> finished;
    std::vector<std::size_t> failed;
    for (const SweepPoint& p : s.points) {
        const std::optional<PointRecord> r = read_point_record(out, p);
        if (!point_done(p, r)) continue;
        finished.push_back(p);
        if (r->exit_code != 0) {
            failed.push_back(p.index);
            std::cerr << fmt::format(FMT_STRING("cncsim sweep collect: point {} failed (exit {}): {}"), p.id(),
                                     r->exit_code, r->message)
                      << std::endl;
        }
    }
    write_results(s.spec, finished, out, {});
    const std::vector<std::size_t> missing = points_to_run(s.points, out);
    std::cerr << fmt::format(FMT_STRING("cncsim sweep collect: {} of {} points done, {} failed, {} missing"),
                             finished.size(), s.points.size(), failed.size(), missing.size())
              << std::endl;
    if (failed.empty() && missing.empty()) return 0;
    std::string ids;
    for (const std::size_t i : missing) ids += (ids.empty() ? "" : " ") + s.points[i].id();
    if (!missing.empty()) std::cerr << "cncsim sweep collect: missing: " << ids << std::endl;
    std::string remove;
    for (const std::size_t i : failed) remove += " " + shell_word(point_record(dir, s.points[i]).string());
    std::vector<std::size_t> again = missing;
    again.insert(again.end(), failed.begin(), failed.end());
    std::sort(again.begin(), again.end());
    std::cerr << "cncsim sweep collect: to run "
              << (failed.empty() ? "the missing points:\n"
                                 : "them again (a failed point's record goes first: a point with one is done):\n");
    if (!failed.empty()) std::cerr << "  rm" << remove << "\n";
    std::cerr << "  sbatch --array=" << array_list(tasks_of(again, sub->per_task)) << " "
              << shell_word((fs::path(dir) / "slurm" / "sweep.sh").string()) << std::endl;
    return 1;
}

}  // namespace

int cmd_sweep(const SweepCommand& c) {
    if (!c.collect_dir.empty()) return collect(c.collect_dir);
    if (c.file.empty() || c.out_dir.empty()) {
        throw BadInput("cncsim sweep",
                       "a sweep file and --out DIR are needed: cncsim sweep SWEEP.toml --out DIR, or "
                       "cncsim sweep collect DIR");
    }
    if (c.per_task != 0 && !c.slurm && !c.point) {
        throw BadInput("--points-per-task", "goes with --slurm (or --point, as the job-array script gives it)");
    }
    Sweep s = read_sweep(c.file);
    if (c.slurm) return submit(s, c);
    if (c.point) return run_task(s, c);
    return run_local(s, c);
}

}  // namespace cnc::sim
