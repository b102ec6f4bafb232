#include "plots/path_plot.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/geometry.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;
using gp::PanelBox;

// Each run's line: one width, so that none covers another's sides; the first solid, every later one dashed
// differently, which tells them apart where paths run apart (and the colours alone do not for every reader). Where
// they coincide, as over most of a job at the whole job's scale, the draw order decides what shows: each run is drawn
// a second time, over the others, in its own share of the cells of a square grid (a hash of the cell picks one run
// per cell), so that along any stretch of shared path every run is on top somewhere.
struct LineStyle {
    const char* dash;  // gnuplot dash type: solid, or (dash, gap, ...) in units that grow with the width
};
constexpr LineStyle kRunStyles[] = {{"solid"}, {"(14,10)"}, {"(6,6)"}, {"(18,6,3,6)"}, {"(2,4)"}};
constexpr double kRunWidth = 2.8;
constexpr double kProgramWidth = 1.2;  // over every run, 0.8 px of its colour left on either side
// The grid's cells, about 12 px: the job's extent in 40 on the whole job, a zoom window in 16.
constexpr double kCellsAcrossJob = 40.0;
constexpr double kCellsAcrossZoom = 16.0;
// The cell's run: x and y in mm, cell_mm and top_runs set per panel.
constexpr const char* kOnTop =
    "on_top(x, y) = abs((int(floor(x / cell_mm)) * 73856093) ^ (int(floor(y / cell_mm)) * 19349663)) % top_runs\n";

// The layout in pixels of the 960 px wide canvas: the key, then the whole job, then rows of zoom panels; sized for
// the SVG's 13 pt text (the PNG's is 10 pt).
constexpr int kKeyTopPx = 6;
constexpr int kMainTopPx = 96;  // room for a two-row key and the title
constexpr int kMainBottomPx = 600;
constexpr int kMainSectionPx = 680;  // with the tic labels and the axis label under the data
constexpr int kZoomRowPx = 370;
constexpr int kZoomTitlePx = 88;  // four title lines
constexpr int kZoomFootPx = 64;   // tic labels and the axis label
constexpr int kLeftPx = 80;
constexpr int kZoomLeftPx = 100;  // tic labels of five or six characters and the axis label
constexpr int kRightPx = 24;

// A tic step of 1, 2 or 5 times a power of ten giving three or four tics over `span`: a zoom panel's tic labels,
// up to six characters, overlap beyond that.
double tic_step(double span) {
    const double raw = span / 3.0;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    const double m = raw / decade;
    return decade * (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0);
}

// A zoom window: three times the run's worst cutting error on each side of it, so that the deviation and the path
// on both sides of it show, at least 20 um, and at most an eighth of the job's extent unless the programmed path
// is further than that. Other runs' paths widen it up to four times to take them in; one further off (steps lost
// before this point) would leave this run's error too small to see, and the title names it instead.
constexpr double kErrorsPerHalfWindow = 3.0;
constexpr double kMaxWidening = 4.0;
constexpr double kMinHalfWindowMm = 0.02;
constexpr double kMargin = 1.25;  // the nearest point of a path in view stays this far inside the window's edge

struct Zoom {
    const PlotRun* run = nullptr;
    double x_mm = 0.0, y_mm = 0.0, half_mm = 0.0;
    std::vector<std::string> title;
};

using Polyline = std::vector<geom::Vec2>;

Polyline tool_polyline(const PlotRun& r, const fs::path& out_dir) {
    Polyline out;
    for (const std::vector<double>& row : gp::read_rows(out_dir / gp::file_of(r, "tool_zoom.dat"), 2))
        out.push_back({row[0], row[1]});
    return out;
}

double distance_to(const Polyline& line, geom::Vec2 p) {
    double best = line.empty() ? INFINITY : geom::distance(line.front(), p);
    for (std::size_t i = 1; i < line.size(); ++i)
        best = std::min(best, geom::Segment::line(line[i - 1], line[i]).distance_to(p));
    return best;
}

std::string figure_um(const nlohmann::json& at) {
    return fmt::format(FMT_STRING("{:.2f} um"), at["contour_um"].get<double>());
}

// The panel's title: whose window, the figure it zooms on and its G-code line; the report's contour error max when
// that is elsewhere (on a rapid: the table's figure includes rapids, docs/metrics.md "Path accuracy"); and the
// runs whose path does not pass through the window, with their distance from its centre.
std::vector<std::string> zoom_title(std::size_t number, const PlotRun& r, const std::vector<std::string>& away) {
    const nlohmann::json& w = r.meta["worst_contour"];
    const bool rapid = w.value("rapid", false);
    std::vector<std::string> title = {
        fmt::format(FMT_STRING("{}: {}, worst {} point"), number, r.label, rapid ? "rapid" : "cutting"),
        "contour error " + figure_um(w) + fmt::format(FMT_STRING(", line {}"), w.value("line", 0))};
    // Larger than the worst cut: on a rapid.
    const nlohmann::json& all = r.meta.value("contour_max", nlohmann::json());
    if (all.is_object() && all["contour_um"].get<double>() > w["contour_um"].get<double>()) {
        title.push_back("all moves: " + figure_um(all) +
                        fmt::format(FMT_STRING(" (rapid, line {})"), all.value("line", 0)));
    }
    if (!away.empty()) {
        std::string text = "not in view:";
        for (std::size_t k = 0; k < away.size(); ++k) text += (k ? ", " : " ") + away[k];
        title.push_back(text);
    }
    return title;
}

// The largest programmed extent of the runs, at least 1 mm.
double program_extent_mm(const std::vector<PlotRun>& runs) {
    double extent_mm = 1.0;
    for (const PlotRun& r : runs) extent_mm = std::max(extent_mm, r.meta.value("program_extent_mm", 0.0));
    return extent_mm;
}

std::vector<Zoom> zooms(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    const double extent_mm = program_extent_mm(runs);
    std::vector<Polyline> paths;
    for (const PlotRun& r : runs) paths.push_back(tool_polyline(r, out_dir));
    std::vector<Zoom> out;
    for (const PlotRun& r : runs) {
        const nlohmann::json& w = r.meta["worst_contour"];
        if (!w.is_object()) continue;
        Zoom z{&r, w["x_mm"].get<double>(), w["y_mm"].get<double>(), 0.0, {}};
        const double err_mm = w["contour_um"].get<double>() / 1000.0;
        const double base_mm =
            std::max({std::min(kErrorsPerHalfWindow * err_mm, extent_mm / 8.0), kMargin * err_mm, kMinHalfWindowMm});
        const geom::Vec2 p{z.x_mm, z.y_mm};
        std::vector<double> distance_mm;
        z.half_mm = base_mm;
        for (const Polyline& path : paths) {
            distance_mm.push_back(distance_to(path, p));
            const double d = kMargin * distance_mm.back();
            if (d <= kMaxWidening * base_mm) z.half_mm = std::max(z.half_mm, d);
        }
        std::vector<std::string> away;
        for (std::size_t k = 0; k < runs.size(); ++k) {
            if (std::isfinite(distance_mm[k]) && distance_mm[k] > z.half_mm) {
                away.push_back(fmt::format(FMT_STRING("{} ({:.3g} mm)"), runs[k].label, distance_mm[k]));
            }
        }
        z.title = zoom_title(out.size() + 1, r, away);
        out.push_back(std::move(z));
    }
    return out;
}

// A panel's plot clauses and the number of runs whose tool path they draw (kOnTop's top_runs).
struct PanelCurves {
    std::vector<std::string> clauses;
    std::size_t tool_paths = 0;
};

// Every run's tool path (from `tool_file`, x and y in columns `x_col` and the next), each run again over the
// others in its own cells (kOnTop), then the programmed path and rapids over them all.
PanelCurves clauses(const std::vector<PlotRun>& runs, const fs::path& out_dir, const std::string& tool_file,
                    int x_col) {
    std::vector<std::string> out, on_top;
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const PlotRun& r = runs[k];
        if (gp::column_range(out_dir / gp::file_of(r, tool_file), 2).rows == 0) continue;
        const std::string file = gp::quoted(gp::file_of(r, tool_file));
        const std::string style = fmt::format(FMT_STRING(" with lines lw {:g} dt {} lc rgb "), kRunWidth,
                                              kRunStyles[k % std::size(kRunStyles)].dash) +
                                  gp::quoted(r.colour);
        out.push_back(file + fmt::format(FMT_STRING(" using {}:{}"), x_col, x_col + 1) + style + " title " +
                      gp::quoted(r.label));
        on_top.push_back(file +
                         fmt::format(FMT_STRING(" using {0}:(on_top(${0}, ${1}) == {2} ? ${1} : NaN)"), x_col,
                                     x_col + 1, on_top.size()) +
                         style + " notitle");
    }
    const std::size_t tool_paths = on_top.size();
    if (tool_paths > 1) out.insert(out.end(), on_top.begin(), on_top.end());
    if (out.empty()) return {};
    const PlotRun& first = runs.front();
    const std::string program = fmt::format(FMT_STRING(" using 1:2 with lines lw {:g} "), kProgramWidth);
    if (gp::column_range(out_dir / gp::file_of(first, "rapids.dat"), 1).rows > 0) {
        out.push_back(gp::quoted(gp::file_of(first, "rapids.dat")) + program + "dt (12,8) lc rgb " +
                      gp::quoted(gp::kProgramColour) + " title 'programmed rapids'");
    }
    if (gp::column_range(out_dir / gp::file_of(first, "program.dat"), 1).rows > 0) {
        out.push_back(gp::quoted(gp::file_of(first, "program.dat")) + program + "dt solid lc rgb " +
                      gp::quoted(gp::kProgramColour) + " title 'programmed'");
    }
    return {out, tool_paths};
}

}  // namespace

std::optional<gp::Script> path_plot(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    gp::Script s({"path", "Tool path over the programmed path", "X [mm]", "Y [mm]"});
    const PanelCurves curves = clauses(runs, out_dir, "tool.dat", 2);
    if (curves.clauses.empty()) return std::nullopt;
    const PanelCurves zoom_curves = clauses(runs, out_dir, "tool_zoom.dat", 1);
    const std::vector<Zoom> zoom = zooms(runs, out_dir);
    const int cols = zoom.size() <= 3 ? static_cast<int>(zoom.size()) : static_cast<int>(zoom.size() + 1) / 2;
    const int rows = cols == 0 ? 0 : (static_cast<int>(zoom.size()) + cols - 1) / cols;
    s.height_px = kMainSectionPx + rows * kZoomRowPx;

    std::ostringstream body;
    // clip two: a programmed line whose both ends lie outside a zoom window still crosses it.
    body << "reset\nset multiplot\nset clip two\nset grid\nset size ratio -1\n"
         << kOnTop
         << fmt::format(FMT_STRING("top_runs = {}\ncell_mm = {:g}\n"), curves.tool_paths,
                        program_extent_mm(runs) / kCellsAcrossJob)
         << fmt::format(FMT_STRING("set key at screen 0.5,{:.5f} center top horizontal box width 2\n"),
                        1.0 - static_cast<double>(kKeyTopPx) / s.height_px);
    const PanelBox main{s.plot.title, kLeftPx, kMainTopPx, gp::kWidthPx - kRightPx, kMainBottomPx};
    s.panels.push_back(main);
    body << gp::margins(main, s.height_px) << "set title " << gp::quoted(s.plot.title) << "\nset xlabel "
         << gp::quoted(s.plot.xlabel) << "\nset ylabel " << gp::quoted(s.plot.ylabel) << "\n";
    for (std::size_t k = 0; k < zoom.size(); ++k) {
        const Zoom& z = zoom[k];
        body << fmt::format(FMT_STRING("set object {0} rect from {1:g},{2:g} to {3:g},{4:g} front fillstyle empty "
                                       "border lc rgb 'black' lw 1.2\n"
                                       "set label {0} '{0}' at {1:g},{4:g} left offset {5:g},0.6 front\n"),
                            k + 1, z.x_mm - z.half_mm, z.y_mm - z.half_mm, z.x_mm + z.half_mm, z.y_mm + z.half_mm,
                            1.5 * static_cast<double>(k));
    }
    body << gp::plot_line(curves.clauses) << "unset object\nunset label\nunset key\n";

    const int col_px = cols == 0 ? gp::kWidthPx : gp::kWidthPx / cols;
    for (std::size_t k = 0; k < zoom.size(); ++k) {
        const Zoom& z = zoom[k];
        const int col = static_cast<int>(k) % cols;
        const int top = kMainSectionPx + static_cast<int>(k) / cols * kZoomRowPx;
        std::string joined;
        for (const std::string& line : z.title) joined += (joined.empty() ? "" : " ") + line;
        // Square, centred in its column: gnuplot keeps a square window's data area square at the box's left.
        const int side = std::min(col_px - kZoomLeftPx - kRightPx, kZoomRowPx - kZoomTitlePx - kZoomFootPx);
        const int left = col * col_px + kZoomLeftPx + (col_px - kZoomLeftPx - kRightPx - side) / 2;
        const PanelBox box{joined, left, top + kZoomTitlePx, left + side, top + kZoomTitlePx + side};
        s.panels.push_back(box);
        body << gp::margins(box, s.height_px) << "set title " << gp::quoted_lines(z.title) << "\n"
             << fmt::format(FMT_STRING("top_runs = {}\ncell_mm = {:g}\n"), zoom_curves.tool_paths,
                            2 * z.half_mm / kCellsAcrossZoom)
             << fmt::format(
                    FMT_STRING("set xrange [{:g}:{:g}]\nset yrange [{:g}:{:g}]\nset xtics {:g}\nset ytics {:g}\n"),
                    z.x_mm - z.half_mm, z.x_mm + z.half_mm, z.y_mm - z.half_mm, z.y_mm + z.half_mm,
                    tic_step(2 * z.half_mm), tic_step(2 * z.half_mm))
             << fmt::format(FMT_STRING("set label 1 '' at {:g},{:g} point pt 6 ps 1.6 lc rgb 'black' front\n"), z.x_mm,
                            z.y_mm)
             << gp::plot_line(zoom_curves.clauses) << "unset label 1\n";
    }
    body << "unset multiplot\n";
    s.body = body.str();
    return s;
}

}  // namespace cnc::sim
