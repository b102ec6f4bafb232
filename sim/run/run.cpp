#include "run/run.hpp"

#include <sstream>

#include "metrics/metrics.hpp"
#include "run/architecture.hpp"
#include "run/job.hpp"
#include "run/program_report.hpp"

namespace cnc::sim {

namespace {

nlohmann::json scenario_json(const Scenario& s, const ArchRun& arch) {
    return {{"name", s.name},
            {"file", s.file},
            {"architecture", s.architecture},
            {"job", s.job_path},
            {"seed", s.seed},
            {"steps_per_mm", {s.machine.x.steps_per_mm(), s.machine.y.steps_per_mm()}},
            {"detail", s.detail},
            {"estimated_s", arch.estimated_s},
            {"max_sim_s", arch.max_sim_s}};
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

}  // namespace

RunOutcome run_scenario(const Scenario& s) {
    const Architecture& architecture = find_architecture(s.architecture, s.file + ": scenario.architecture");
    const Job job = architecture.runs_job ? load_job(s) : Job{};
    RunOutcome out;
    out.arch = architecture.run(s, job);
    if (job.program) {
        for (Warning& w : laser_warnings(*job.program, architecture.laser_switching)) {
            out.arch.warnings.push_back(std::move(w));
        }
    }
    out.metrics = metrics::compute_metrics(out.arch.input);
    const ArchRun& arch = out.arch;
    const metrics::RunMetrics& m = out.metrics;

    out.ok = arch.ok;
    out.failure = arch.failure;
    out.report = {{"scenario", scenario_json(s, arch)},
                  {"metrics", metrics::to_json(m, s.detail)},
                  {s.architecture, arch.details},
                  {"warnings", warnings_json(arch.warnings, s.detail)},
                  {"gcode", job.program ? program_json(*job.program) : nlohmann::json(nullptr)},
                  {"ok", arch.ok}};
    if (!arch.ok) {
        out.report["failure"] = arch.failure;
        out.report["metrics_partial"] = true;
    }

    std::ostringstream text;
    text << "cncsim run: " << s.name << " (" << s.architecture << "), job " << s.job_path << "\n\n";
    if (!arch.ok) {
        text << "PARTIAL: the run failed (" << arch.failure
             << ").\nThe figures below cover only what ran before it stopped; they are not a result.\n\n";
    }
    text << metrics::summary_table(m) << '\n'
         << (job.program ? program_text(*job.program) : std::string()) << '\n'
         << arch.details_text;
    for (const WarningGroup& g : group_warnings(arch.warnings)) text << "warning: " << summary_line(g) << '\n';
    out.summary = text.str();
    return out;
}

}  // namespace cnc::sim
