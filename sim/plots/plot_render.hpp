// Renders the plots of one or more runs with gnuplot, as SVG and PNG, from the data files write_plot_data wrote.
// Each plot is a gnuplot script of its own (data/<name>.gp, paths relative to the output folder), loaded once per
// terminal by one gnuplot process, so the figures can be re-rendered or edited by hand.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace cnc::sim {

struct PlotRun {
    std::string label;     // in titles and keys: the architecture, or "architecture: variant"
    std::string colour;    // its curves' and bars' colour (#rrggbb)
    std::string data_dir;  // relative to the output folder: where write_plot_data wrote (data/<file stem>)
    nlohmann::json meta;   // its meta.json
};

// A run to plot: its folder data/<file_stem> under the output folder, and how it is shown.
struct PlotSource {
    std::string file_stem;
    std::string label;
    std::string colour;
};

struct Plot {
    std::string name;  // <name>.svg and <name>.png in the output folder
    std::string title, xlabel, ylabel;
};

// An architecture's colour in every plot and on the HTML page (Architecture::plot_colour).
std::string arch_colour(const std::string& architecture);
// The colour of the k-th of n variants of an architecture whose colour is `base` (#rrggbb): `base` itself for one;
// for more, hues spread around base's (greys from dark to light for a colour without hue) at two alternating
// lightnesses dark enough for a thin line on white, so that neighbours differ in both.
std::string variant_colour(const std::string& base, std::size_t k, std::size_t n);

// Reads data/<file_stem>/meta.json of each source under `out_dir` (a run refused before simulating has none).
std::vector<PlotRun> load_plot_runs(const std::filesystem::path& out_dir, const std::vector<PlotSource>& sources);

// Writes the scripts, runs gnuplot in out_dir and returns the plots it drew (a plot with no data in any run is left
// out; the load angle and lost steps plots exist only when a run reports them). Also writes plots.json, the list
// (with the path plot's panels: docs/plots.md).
// Throws std::runtime_error when gnuplot is missing or fails.
std::vector<Plot> render_plots(const std::vector<PlotRun>& runs, const std::filesystem::path& out_dir);

}  // namespace cnc::sim
