// Plots an architecture draws of data only it has (the lathe's passes), beside the plots every run gets
// (plot_data.hpp): it hands the data tables and a gnuplot script in ArchRun::plots, write_plot_data writes the
// tables into the run's data folder and lists the plots in meta.json, and render_plots draws them with the same
// header, terminals and plots.json entry as the others (docs/plots.md).
#pragma once
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace cnc::sim {

// A gnuplot data file: a `#` line of column names, then the rows in blocks (a block per pass, say), which gnuplot
// reads as `index 0`, `index 1`, ... (blocks are two blank lines apart).
struct PlotTable {
    std::string file;     // its name in the run's data folder
    std::string columns;  // "revolution phase_error_um"
    std::vector<std::vector<std::vector<double>>> blocks;
};

struct ArchPlot {
    std::string name;                   // <name>.svg and <name>.png: must differ from the plots every run gets
    std::string title, xlabel, ylabel;  // the labels with their unit in brackets
    std::vector<PlotTable> tables;
    // The gnuplot commands after the header (title, labels, grid, key): the string variable `data_dir` holds the
    // tables' folder, relative to the folder gnuplot runs in (`plot data_dir.'/phase_error.dat' index 0 ...`).
    std::string script;
};

// Writes each plot's tables into `dir`; returns the plots' list for meta.json ("arch_plots").
nlohmann::json write_arch_plots(const std::vector<ArchPlot>& plots, const std::filesystem::path& dir);

}  // namespace cnc::sim
