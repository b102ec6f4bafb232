#include "run/run.hpp"

#include <sstream>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "architectures/catalog.hpp"
#include "architectures/registry.hpp"
#include "metrics/metrics.hpp"
#include "metrics/pulse/commanded_rates.hpp"
#include "metrics/report/report.hpp"
#include "metrics/report/zero_notes.hpp"
#include "run/job.hpp"
#include "run/program_report.hpp"

namespace cnc::sim {

namespace {

// The machine every architecture of a comparison shares (its columns show it): per axis the resolution (the
// microsteps the controller counts, and the full steps the motor turns: what loads the dynamic motor) and the
// limits, and the rapid speed.
nlohmann::json machine_json(const Scenario& s) {
    nlohmann::json out = {{"rapid_feed_mm_per_min", s.interpreter.rapid_feed_mm_per_min}};
    for (const auto& [name, axis] : {std::pair{"x", &s.machine.x}, std::pair{"y", &s.machine.y}}) {
        out[name] = {{"steps_per_mm", axis->steps_per_mm()},
                     {"microsteps", axis->microsteps},
                     {"full_steps_per_mm", axis->steps_per_mm() / axis->microsteps},
                     {"max_velocity_mm_per_s", axis->limits.max_velocity_mm_per_s},
                     {"max_accel_mm_per_s2", axis->limits.max_accel_mm_per_s2},
                     {"max_jerk_mm_per_s3", axis->limits.max_jerk_mm_per_s3}};
    }
    return out;
}

nlohmann::json scenario_json(const Scenario& s, const ArchRun& arch) {
    nlohmann::json j = {{"name", s.name},
                        {"file", s.file},
                        {"architecture", s.architecture},
                        {"job", s.job_path},
                        {"seed", s.seed},
                        {"steps_per_mm", {s.machine.x.steps_per_mm(), s.machine.y.steps_per_mm()}},
                        {"machine", machine_json(s)},
                        {"detail", s.detail},
                        {"estimated_s", arch.estimated_s},
                        {"max_sim_s", arch.max_sim_s}};
    if (!s.drawing_path.empty()) j["drawing"] = s.drawing_path;  // the DXF job, whose G-code "job" is
    return j;
}

// One entry per kind (common/warning.hpp); with `detail` also every warning of the kind, as worded one by one.
nlohmann::json warnings_json(const std::vector<Warning>& warnings, bool detail) {
    nlohmann::json out = nlohmann::json::array();
    for (const WarningGroup& g : group_warnings(warnings)) {
        nlohmann::json j = {{"kind", g.kind}, {"count", g.count}, {"first", g.first}, {"message", g.message}};
        if (detail) {
            nlohmann::json& all = j["all"] = nlohmann::json::array();
            for (const std::size_t i : g.members) all.push_back(to_string(warnings[i]));
        }
        out.push_back(std::move(j));
    }
    return out;
}

// The first programmed move that stepped an axis, from its first to its last STEP edge.
std::optional<TimeSpan> first_move(const metrics::RunMetrics& m) {
    for (std::size_t i = 0; i < m.moves.size(); ++i) {
        const metrics::MoveMetrics move = m.moves.at(i);
        if (move.t_first_edge_ps && move.t_last_edge_ps) return TimeSpan{*move.t_first_edge_ps, *move.t_last_edge_ps};
    }
    return std::nullopt;
}

// The registry entry named by scenario.architecture runs it.
template <typename... Entries>
ArchRun run_architecture(const Scenario& s, const Job& job, EntryList<Entries...>) {
    ArchRun run;
    const bool ran =
        ((s.architecture == Entries::architecture().name() ? (run = Entries::run(s, job), true) : false) || ...);
    if (!ran) throw std::logic_error("no registry entry runs " + s.architecture);
    return run;
}

}  // namespace

RunOutcome run_scenario(const Scenario& s) {
    const Architecture& architecture = find_architecture(s.architecture, s.file + ": scenario.architecture");
    const Job job = architecture.job_use().runs_job ? load_job(s, architecture) : Job{};
    RunOutcome out;
    out.arch = run_architecture(s, job, Registry{});
    out.arch.warnings.insert(out.arch.warnings.end(), job.move_warnings.begin(), job.move_warnings.end());
    out.arch.warnings.insert(out.arch.warnings.begin(), job.warnings.begin(), job.warnings.end());
    out.metrics = out.arch.metrics ? std::move(*out.arch.metrics) : metrics::compute_metrics(out.arch.input);
    if (out.arch.trace && !out.arch.first_move) out.arch.first_move = first_move(out.metrics);
    const ArchRun& arch = out.arch;
    const metrics::RunMetrics& m = out.metrics;

    out.ok = arch.ok;
    out.detail = s.detail;
    out.failure = arch.failure;
    out.report = {{"scenario", scenario_json(s, arch)},
                  {"metrics", metrics::to_json(m, s.detail, metrics::MoveColumns::Streamed)},
                  {s.architecture, arch.details},
                  {"warnings", warnings_json(arch.warnings, s.detail)},
                  {"gcode", job.program ? program_json(*job.program) : nlohmann::json(nullptr)},
                  {"ok", arch.ok}};
    if (!arch.clock.is_null()) out.report["clock"] = arch.clock;
    // What `analyze --commanded` splits pulse runs by; per servo period, so only with --detail.
    if (!arch.input.rate_segments.empty()) {
        out.report["commanded_rates"] = s.detail ? metrics::commanded_rates_json(arch.input) : nlohmann::json(nullptr);
    }
    if (!arch.ok) {
        out.report["failure"] = arch.failure;
        out.report["metrics_partial"] = true;
    }

    std::ostringstream text;
    text << "cncsim run: " << s.name << " (" << s.architecture << ")"
         << (s.job_path.empty() ? std::string() : ", job " + s.job_path)
         << (s.drawing_path.empty() ? std::string() : " (the G-code of " + s.drawing_path + ")") << "\n\n";
    if (!arch.ok) {
        text << "PARTIAL: the run failed (" << arch.failure
             << ").\nThe figures below cover only what ran before it stopped; they are not a result.\n\n";
    }
    // A controller without STEP/DIR axes (the lathe's DC motor) has no pulse figures to tabulate.
    if (!m.axes.empty()) text << metrics::summary_table(m) << '\n';
    std::string clock_lines = arch.clock_text;
    for (const std::string& note : metrics::zero_by_construction(out.report)) clock_lines += note + '\n';
    if (!clock_lines.empty()) text << clock_lines << '\n';
    text << (job.program ? program_text(*job.program) : std::string()) << '\n' << arch.details_text;
    for (const WarningGroup& g : group_warnings(arch.warnings)) text << "warning: " << summary_line(g) << '\n';
    out.summary = text.str();
    return out;
}

void write_report(std::ostream& out, const RunOutcome& run) {
    const metrics::StreamedMember moves{{"metrics", "moves"}, [&run](std::ostream& os, int depth) {
                                            metrics::write_move_columns(os, run.metrics, run.detail, depth);
                                        }};
    metrics::write_report_text(out, run.report, &moves);
}

}  // namespace cnc::sim
