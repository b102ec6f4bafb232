// The path plot: the whole job with every run's tool path and the programmed path over them, and under it a zoom
// panel per run around that run's worst cutting point, each with the programmed path and every run's tool path.
#pragma once
#include <filesystem>
#include <optional>
#include <vector>

#include "plots/gnuplot_script.hpp"

namespace cnc::sim {

// Nothing when no run has tool samples.
std::optional<gp::Script> path_plot(const std::vector<PlotRun>& runs, const std::filesystem::path& out_dir);

}  // namespace cnc::sim
