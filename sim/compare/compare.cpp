#include "compare/compare.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "common/text_format.hpp"

extern char** environ;

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

struct Row {
    const char* label;
    const char* pointer;  // JSON pointer into a run report
    const char* format;   // printf format of the value
    bool setting = false; // what the run was given (shown for a failed run too), not a result
};

// The machine each run used, then the headline numbers of DESIGN.md §4 in the order a reader compares them.
constexpr Row kRows[] = {
    {"machine: X steps/mm", "/scenario/machine/x/steps_per_mm", "%.4f", true},
    {"machine: X velocity max [mm/s]", "/scenario/machine/x/max_velocity_mm_per_s", "%.1f", true},
    {"machine: X accel max [mm/s^2]", "/scenario/machine/x/max_accel_mm_per_s2", "%.0f", true},
    {"machine: X jerk max [mm/s^3]", "/scenario/machine/x/max_jerk_mm_per_s3", "%.0f", true},
    {"machine: Y steps/mm", "/scenario/machine/y/steps_per_mm", "%.4f", true},
    {"machine: Y velocity max [mm/s]", "/scenario/machine/y/max_velocity_mm_per_s", "%.1f", true},
    {"machine: Y accel max [mm/s^2]", "/scenario/machine/y/max_accel_mm_per_s2", "%.0f", true},
    {"machine: Y jerk max [mm/s^3]", "/scenario/machine/y/max_jerk_mm_per_s3", "%.0f", true},
    {"machine: rapid speed [mm/min]", "/scenario/machine/rapid_feed_mm_per_min", "%.1f", true},
    {"job time [s]", "/metrics/job/job_time_s", "%.4f"},
    {"motion time [s]", "/metrics/job/motion_time_s", "%.4f"},
    {"dead time total [ms]", "/metrics/job/dead_total_ms", "%.3f"},
    {"dead time mean [ms]", "/metrics/job/dead_mean_ms", "%.3f"},
    {"TIE max [ns]", "/metrics/pulse/tie_max_ns", "%.3f"},
    {"period jitter p-p max [ns]", "/metrics/pulse/jitter_pp_max_ns", "%.3f"},
    {"rate error worst [%]", "/metrics/pulse/rate_error_worst_pct", "%+.4f"},
    {"sync error max [us]", "/metrics/pulse/sync_max_us", "%.1f"},
    {"feed error max [%]", "/metrics/feed/feed_error_max_abs_pct", "%.4f"},
    {"contour error max [um]", "/metrics/path/contour_max_um", "%.2f"},
    {"contour error rms [um]", "/metrics/path/contour_rms_um", "%.2f"},
    {"following error max [um]", "/metrics/path/following_max_um", "%.2f"},
    {"job end error [um]", "/metrics/path/job_end_um", "%.2f"},
    {"DRV8825 violations", "/metrics/pulse/driver_violations", "%.0f"},
    {"laser dwell [ms]", "/metrics/laser/dwell_ms", "%.3f"},
    {"laser on in rapids [ms]", "/metrics/laser/on_in_rapid_ms", "%.3f"},
};

// A failed run's figures cover only what ran before it stopped: never shown as a result (its JSON keeps them
// apart as partial_metrics).
std::string cell(const CompareColumn& c, const Row& row) {
    if (c.report.is_null() || (c.exit_code != 0 && !row.setting)) return "-";
    const nlohmann::json::json_pointer ptr(row.pointer);
    if (!c.report.contains(ptr) || !c.report.at(ptr).is_number()) return "-";
    return format(row.format, c.report.at(ptr).get<double>());
}

std::string status(const CompareColumn& c) {
    if (c.exit_code == 0) return "ok";
    return c.exit_code == 2 ? "bad input" : "failed";
}

// Runs argv and waits; the child's stdout goes to /dev/null (its summary), stderr stays the user's.
int spawn_and_wait(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int err = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (err != 0) throw std::runtime_error(std::string("cannot start ") + argv[0] + ": " + std::strerror(err));
    int wstatus = 0;
    while (waitpid(pid, &wstatus, 0) < 0) {
        if (errno != EINTR) throw std::runtime_error("waitpid failed");
    }
    return WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 1;
}

}  // namespace

std::vector<CompareColumn> run_compare(const std::string& self_exe, const std::string& scenario,
                                       const std::vector<std::string>& architectures,
                                       const std::vector<std::string>& sets) {
    std::string dir_template = (fs::temp_directory_path() / "cncsim-compare-XXXXXX").string();
    if (mkdtemp(dir_template.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder");
    const fs::path dir(dir_template);
    std::vector<CompareColumn> columns;
    for (const std::string& arch : architectures) {
        const fs::path report = dir / (arch + ".json");
        // One child at a time, its progress as whole lines (a line per 10 % of its estimate) named by architecture,
        // between the parent's start and end lines.
        std::vector<std::string> args = {self_exe, "run", scenario, "--progress", "log", "--set",
                                         "scenario.architecture=" + arch};
        for (const std::string& s : sets) {
            args.push_back("--set");
            args.push_back(s);
        }
        args.push_back("--report");
        args.push_back(report.string());
        CompareColumn c;
        c.architecture = arch;
        std::cerr << "cncsim compare: " << arch << " running" << std::endl;
        const auto start = std::chrono::steady_clock::now();
        c.exit_code = spawn_and_wait(args);
        const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
        std::cerr << "cncsim compare: " << arch << " " << status(c) << format(" after %.1f s", wall.count())
                  << std::endl;
        std::ifstream in(report);
        if (in) c.report = nlohmann::json::parse(in);
        columns.push_back(std::move(c));
    }
    fs::remove_all(dir);
    return columns;
}

nlohmann::json compare_json(const std::vector<CompareColumn>& columns) {
    nlohmann::json out = nlohmann::json::array();
    for (const CompareColumn& c : columns) {
        nlohmann::json metrics = nlohmann::json::object();
        for (const Row& row : kRows) {
            if (row.setting) continue;
            const nlohmann::json::json_pointer ptr(row.pointer);
            metrics[row.pointer + 1] =
                !c.report.is_null() && c.report.contains(ptr) ? c.report.at(ptr) : nlohmann::json(nullptr);
        }
        nlohmann::json column = {{"architecture", c.architecture},
                                 {"status", status(c)},
                                 {"exit_code", c.exit_code},
                                 {"machine", c.report.is_null() ? nlohmann::json(nullptr)
                                                                : c.report.value("scenario", nlohmann::json::object())
                                                                      .value("machine", nlohmann::json())},
                                 {"warnings", c.report.is_null() ? nlohmann::json::array()
                                                                 : c.report.value("warnings", nlohmann::json::array())}};
        if (c.exit_code == 0) {
            column["metrics"] = metrics;
        } else {
            column["metrics"] = nullptr;
            column["partial_metrics"] = metrics;
            column["failure"] = c.report.is_null() ? nlohmann::json(nullptr) : c.report.value("failure", nlohmann::json());
        }
        out.push_back(std::move(column));
    }
    return out;
}

std::string compare_table(const std::vector<CompareColumn>& columns, TableFormat format_kind) {
    if (format_kind == TableFormat::Json) return compare_json(columns).dump(2) + "\n";
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> head = {"metric"};
    std::vector<std::string> st = {"status"};
    for (const CompareColumn& c : columns) {
        head.push_back(c.architecture);
        st.push_back(status(c));
    }
    rows.push_back(head);
    rows.push_back(st);
    for (const Row& row : kRows) {
        std::vector<std::string> r = {row.label};
        for (const CompareColumn& c : columns) r.push_back(cell(c, row));
        rows.push_back(r);
    }
    std::ostringstream os;
    if (format_kind == TableFormat::Csv) {
        for (const auto& r : rows) {
            for (std::size_t i = 0; i < r.size(); ++i) os << (i ? "," : "") << '"' << r[i] << '"';
            os << '\n';
        }
        return os.str();
    }
    std::vector<std::size_t> width(rows.front().size(), 0);
    for (const auto& r : rows) {
        for (std::size_t i = 0; i < r.size(); ++i) width[i] = std::max(width[i], r[i].size());
    }
    const bool md = format_kind == TableFormat::Markdown;
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
    return os.str();
}

}  // namespace cnc::sim
