#include "run/run.hpp"

#include <sstream>

#include "metrics/metrics.hpp"
#include "run/job.hpp"
#include "systems/atmega/atmega_system.hpp"
#include "systems/fpga_uart_system.hpp"
#include "systems/spi_fpga/spi_fpga_system.hpp"

namespace cnc::sim {

namespace {

nlohmann::json scenario_json(const Scenario& s, const ArchRun& arch) {
    return {{"name", s.name},
            {"file", s.file},
            {"architecture", s.architecture},
            {"job", s.job_path},
            {"seed", s.seed},
            {"steps_per_mm", {s.machine.x.steps_per_mm(), s.machine.y.steps_per_mm()}},
            {"estimated_s", arch.estimated_s},
            {"max_sim_s", arch.max_sim_s}};
}

}  // namespace

RunOutcome run_scenario(const Scenario& s) {
    const Job job = load_job(s);
    RunOutcome out;
    if (s.architecture == "atmega") {
        out.arch = run_atmega(s, job);
    } else if (s.architecture == "spi-fpga") {
        out.arch = run_spi_fpga(s, job);
    } else {
        out.arch = run_fpga_uart(s, job);
    }
    out.metrics = metrics::compute_metrics(out.arch.input);
    const ArchRun& arch = out.arch;
    const metrics::RunMetrics& m = out.metrics;

    out.ok = arch.ok;
    out.failure = arch.failure;
    out.report = {{"scenario", scenario_json(s, arch)},
                  {"metrics", metrics::to_json(m)},
                  {s.architecture, arch.details},
                  {"warnings", arch.warnings},
                  {"ok", arch.ok}};
    if (!arch.ok) out.report["failure"] = arch.failure;

    std::ostringstream text;
    text << "cncsim run: " << s.name << " (" << s.architecture << "), job " << s.job_path << "\n\n"
         << metrics::summary_table(m) << '\n'
         << arch.details_text;
    for (const std::string& w : arch.warnings) text << "warning: " << w << '\n';
    out.summary = text.str();
    return out;
}

}  // namespace cnc::sim
