// `cncsim run --plots DIR` (the plots of one run) and `--plot-data DIR` (only the data files: what `compare` asks
// of each architecture's child before it draws them all together).
#pragma once
#include <string>

#include "run/run.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

// Either folder may be empty (not asked for). Plot data goes to plot_data_dir, or to plots_dir/data/<architecture>.
void write_run_plots(const RunOutcome& out, const Scenario& s, const std::string& plots_dir,
                     const std::string& plot_data_dir);

}  // namespace cnc::sim
