#include "plots/run_plots.hpp"

#include <filesystem>

#include "plots/plot_data.hpp"
#include "plots/plot_render.hpp"

namespace cnc::sim {

void write_run_plots(const RunOutcome& out, const Scenario& s, const std::string& plots_dir,
                     const std::string& plot_data_dir) {
    if (!plot_data_dir.empty()) write_plot_data(s.architecture, out.arch, out.metrics, plot_data_dir);
    if (plots_dir.empty()) return;
    const std::filesystem::path dir(plots_dir);
    write_plot_data(s.architecture, out.arch, out.metrics, dir / "data" / s.architecture);
    render_plots(load_plot_runs(dir, {{s.architecture, s.architecture, arch_colour(s.architecture)}}), dir);
}

}  // namespace cnc::sim
