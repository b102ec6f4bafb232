#include "sweep/sweep_run.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "compare/spawn.hpp"
#include "output/output_file.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int sig) {
    g_stop_signal = sig;
}

// SIGINT and SIGTERM set g_stop_signal and interrupt waitpid (no SA_RESTART) while the sweep runs; the previous
// handlers come back after it.
class StopSignals {
public:
    StopSignals() {
        g_stop_signal = 0;
        struct sigaction sa {};
        sa.sa_handler = on_stop_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGINT, &sa, &m_int);
        sigaction(SIGTERM, &sa, &m_term);
    }
    ~StopSignals() {
        sigaction(SIGINT, &m_int, nullptr);
        sigaction(SIGTERM, &m_term, nullptr);
    }
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

private:
    struct sigaction m_int {};
    struct sigaction m_term {};
};

std::string duration_text(double s) {
    const auto total = static_cast<long long>(s + 0.5);
    return total >= 3600 ? fmt::format(FMT_STRING("{}:{:02d}:{:02d}"), total / 3600, total / 60 % 60, total % 60)
                         : fmt::format(FMT_STRING("{}:{:02d}"), total / 60, total % 60);
}

// "cncsim sweep: 12/60 points done, 1 failed, 2 running, ETA 0:35": redrawn on a terminal, else a line per 5 % of
// the points and at the end.
class Progress {
public:
    Progress(std::size_t total, std::size_t done_before) : m_total(total), m_before(done_before) {
        m_tty = isatty(STDERR_FILENO) != 0;
    }
    void show(std::size_t done, std::size_t failed, std::size_t running, bool last) {
        const std::size_t ran = done - m_before;
        const double elapsed = std::chrono::duration<double>(Clock::now() - m_start).count();
        const std::string eta =
            ran == 0 ? "" : ", ETA " + duration_text(elapsed / ran * static_cast<double>(m_total - done));
        const std::string line = fmt::format(FMT_STRING("cncsim sweep: {}/{} points done, {} failed, {} running{}"),
                                             done, m_total, failed, running, eta);
        const std::size_t step = std::max<std::size_t>(1, m_total / 20);
        if (m_tty) {
            std::cerr << '\r' << line << "\033[K" << (last ? "\n" : "") << std::flush;
        } else if ((last && done != m_shown) || done / step != m_shown / step) {
            std::cerr << line << std::endl;
            m_shown = done;
        }
    }

private:
    std::size_t m_total;
    std::size_t m_before;
    std::size_t m_shown = 0;
    bool m_tty = false;
    Clock::time_point m_start = Clock::now();
};

std::vector<std::string> child_args(const SweepRunOptions& o, const SweepPoint& p) {
    std::vector<std::string> args = {o.self_exe, "run"};
    args.insert(args.end(), o.input.begin(), o.input.end());
    args.insert(args.end(), {"--progress", "off"});
    for (const std::string& s : p.sets) args.insert(args.end(), {"--set", s});
    args.insert(args.end(), {"--report", point_report(o.out_dir, p).string()});
    return args;
}

fs::path point_log(const fs::path& out_dir, const SweepPoint& p) {
    return out_dir / "points" / (p.id() + ".log");
}

}  // namespace

std::string read_text(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

fs::path point_report(const fs::path& out_dir, const SweepPoint& p) {
    return out_dir / "points" / (p.id() + ".json");
}

fs::path point_record(const fs::path& out_dir, const SweepPoint& p) {
    return out_dir / "points" / (p.id() + ".done.json");
}

std::optional<PointRecord> read_point_record(const fs::path& out_dir, const SweepPoint& p) {
    const fs::path file = point_record(out_dir, p);
    if (!fs::exists(file)) return std::nullopt;
    return parse_record(read_text(file));
}

SweepRunOutcome run_points(const std::vector<SweepPoint>& points, const SweepRunOptions& options,
                           const std::function<void(const SweepPoint&)>& after_point) {
    SweepRunOutcome out;
    std::vector<const SweepPoint*> todo;
    for (const SweepPoint& p : points) {
        const std::optional<PointRecord> r = read_point_record(options.out_dir, p);
        if (!point_done(p, r)) {
            todo.push_back(&p);
            continue;
        }
        ++out.already_done;
        if (r->exit_code != 0) ++out.failed;
    }
    if (out.already_done > 0) {
        std::cerr << fmt::format(FMT_STRING("cncsim sweep: {} of {} points done by an earlier run, {} to run"),
                                 out.already_done, points.size(), todo.size())
                  << std::endl;
    }
    fs::create_directories(options.out_dir / "points");
    const StopSignals signals;
    Progress progress(points.size(), out.already_done);
    std::map<pid_t, const SweepPoint*> running;
    std::size_t next = 0;
    bool stopping = false;
    std::exception_ptr error;
    const auto stop_children = [&] {
        if (stopping) return;
        stopping = true;
        for (const auto& [pid, point] : running) kill(pid, SIGINT);
    };
    while (true) {
        if (g_stop_signal != 0) stop_children();
        while (!stopping && next < todo.size() && running.size() < options.jobs) {
            const SweepPoint& p = *todo[next++];
            running[spawn_child(child_args(options, p), "", point_log(options.out_dir, p).string())] = &p;
        }
        if (running.empty()) break;
        int wstatus = 0;
        const pid_t pid = waitpid(-1, &wstatus, 0);
        if (pid < 0) {
            if (errno == EINTR) continue;
            throw std::runtime_error(std::string("waitpid failed: ") + std::strerror(errno));
        }
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        const SweepPoint& p = *it->second;
        running.erase(it);
        // Stopped by our SIGINT (or the terminal's): not a result, the point runs again next time.
        if (WIFSIGNALED(wstatus) && (stopping || g_stop_signal != 0)) continue;
        PointRecord record{p.sets, WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus), ""};
        if (record.exit_code != 0) {
            record.message = WIFSIGNALED(wstatus)
                                 ? fmt::format(FMT_STRING("killed by signal {} ({})"), WTERMSIG(wstatus),
                                               strsignal(WTERMSIG(wstatus)))
                                 : failure_message(read_text(point_log(options.out_dir, p)), record.exit_code);
        }
        write_output_file(point_record(options.out_dir, p).string(), "--out", record_json(record).dump(1) + "\n");
        ++out.ran;
        if (record.exit_code != 0) ++out.failed;
        progress.show(out.already_done + out.ran, out.failed, running.size(), false);
        if (record.exit_code == 0 && !error) {
            try {
                after_point(p);
            } catch (...) {
                error = std::current_exception();
                stop_children();
            }
        }
    }
    out.interrupted = g_stop_signal != 0 || stopping;
    if (error) std::rethrow_exception(error);
    progress.show(out.already_done + out.ran, out.failed, 0, true);
    return out;
}

}  // namespace cnc::sim
