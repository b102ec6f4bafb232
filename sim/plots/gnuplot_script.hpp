// The pieces every plot's gnuplot script is made of: reading a data file's extent, quoting, the curves of the runs,
// the plot command; shared by plot_render.cpp and path_plot.cpp.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "plots/plot_render.hpp"

namespace cnc::sim::gp {

inline constexpr int kWidthPx = 960;  // every plot's width; the height is the plot's own
inline constexpr int kHeightPx = 640;

// The programmed (commanded) path and speed: darker than every architecture colour, and apart from them (the
// Okabe-Ito palette and the ideal controller's black) in hue, so that neither the eye nor a pixel count mistakes
// one for the other; and unlike black, it is no axis, border or text colour.
inline constexpr const char* kProgramColour = "#7a0177";

// Rows of a data file and the range of one column (1-based), so that a script never plots an empty file and a
// constant series gets a visible range instead of gnuplot's "empty range" warning.
struct ColumnRange {
    std::size_t rows = 0;
    double lo = 0.0;
    double hi = 0.0;
};
ColumnRange column_range(const std::filesystem::path& file, int column);
// Columns 1 .. `columns` in one reading of the file.
std::vector<ColumnRange> column_ranges(const std::filesystem::path& file, int columns);
ColumnRange merge(ColumnRange a, const ColumnRange& b);

// The rows of a data file's first columns (x y ...), blank and `#` lines skipped.
std::vector<std::vector<double>> read_rows(const std::filesystem::path& file, int columns);

// A gnuplot string literal: single-quoted (no escapes), or double-quoted where it holds line breaks.
std::string quoted(const std::string& s);
std::string quoted_lines(const std::vector<std::string>& lines);

std::string file_of(const PlotRun& r, const std::string& name);

// A figure's box in the PNG and SVG, pixels from the top left: where one panel's data area lies (plots.json).
struct PanelBox {
    std::string title;
    int left_px = 0, top_px = 0, right_px = 0, bottom_px = 0;
};

struct Script {
    explicit Script(Plot p) : plot(std::move(p)) {}
    Plot plot;
    int height_px = kHeightPx;
    std::string body;
    std::vector<PanelBox> panels;  // only where the script sets each panel's box itself (the path plot)
};

// reset, the plot's title and labels, a grid, and the key outside the data, over it: a key inside covers curves.
std::string header(const Plot& p);

// A constant range (e.g. TIE 0 on every edge) opens to +-1 around it.
std::string yrange_for(const ColumnRange& r);

// One curve per run that has rows: `using` columns and style; empty when no run has data.
struct Curves {
    std::vector<std::string> clauses;
    ColumnRange y;
};
Curves curves(const std::vector<PlotRun>& runs, const std::filesystem::path& out_dir, const std::string& file, int ycol,
              const std::string& using_style, const std::string& suffix = "");

std::string plot_line(const std::vector<std::string>& clauses);

// Writes each script as data/<name>.gp under out_dir and data/plots.gp, which renders them all as <name>.svg and
// <name>.png, and plots.json, the list; runs gnuplot in out_dir and returns the plots. Throws std::runtime_error
// when gnuplot is missing or fails.
std::vector<Plot> render_scripts(const std::vector<Script>& scripts, const std::filesystem::path& out_dir);

// gnuplot's margins placing a panel's data area at a box given in pixels of a width_px x height_px canvas.
std::string margins(const PanelBox& box, int height_px);

}  // namespace cnc::sim::gp
