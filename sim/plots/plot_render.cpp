#include "plots/plot_render.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "architectures/catalog.hpp"
#include "compare/spawn.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

constexpr const char* kProgramColour = "#9a9a9a";
// Dead-time causes, in the order the architectures report them; the palette avoids the architecture colours.
constexpr const char* kCauseColours[] = {"#e69f00", "#56b4e9", "#f0e442", "#cc79a7", "#999999",
                                         "#000000", "#882255", "#44aa99", "#ddcc77", "#117733"};
// The gaps inside a programmed move (between its pieces) where the run reports no causes.
constexpr const char* kInsideColour = "#999999";
constexpr int kWidthPx = 960;
constexpr int kHeightPx = 640;
constexpr int kPanelHeightPx = 260;

// Rows of a data file and the range of one column (1-based), so that a script never plots an empty file and a
// constant series gets a visible range instead of gnuplot's "empty range" warning.
struct ColumnRange {
    std::size_t rows = 0;
    double lo = 0.0;
    double hi = 0.0;
};

ColumnRange column_range(const fs::path& file, int column) {
    ColumnRange r;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        double v = 0.0;
        for (int c = 0; c < column; ++c) fields >> v;
        if (!fields) continue;
        r.lo = r.rows == 0 ? v : std::min(r.lo, v);
        r.hi = r.rows == 0 ? v : std::max(r.hi, v);
        ++r.rows;
    }
    return r;
}

ColumnRange merge(ColumnRange a, const ColumnRange& b) {
    if (b.rows == 0) return a;
    if (a.rows == 0) return b;
    return {a.rows + b.rows, std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

std::string quoted(const std::string& s) {
    std::string out = "'";
    for (const char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

std::string file_of(const PlotRun& r, const std::string& name) {
    return r.data_dir + "/" + name;
}

struct Script {
    explicit Script(Plot p) : plot(std::move(p)) {}
    Plot plot;
    int height_px = kHeightPx;
    std::string body;
};

std::string header(const Plot& p) {
    return "reset\nset title " + quoted(p.title) + "\nset xlabel " + quoted(p.xlabel) + "\nset ylabel " +
           quoted(p.ylabel) + "\nset grid\nset key top right box opaque\n";
}

// A constant range (e.g. TIE 0 on every edge) opens to +-1 around it.
std::string yrange_for(const ColumnRange& r) {
    if (r.rows == 0 || r.lo != r.hi) return "";
    return fmt::format(FMT_STRING("set yrange [{:g}:{:g}]\n"), r.lo - 1.0, r.hi + 1.0);
}

// One curve per run that has rows: `using` columns and style; empty when no run has data.
struct Curves {
    std::vector<std::string> clauses;
    ColumnRange y;
};

Curves curves(const std::vector<PlotRun>& runs, const fs::path& out_dir, const std::string& file, int ycol,
              const std::string& using_style, const std::string& suffix = "") {
    Curves c;
    for (const PlotRun& r : runs) {
        const ColumnRange y = column_range(out_dir / file_of(r, file), ycol);
        if (y.rows == 0) continue;
        c.y = merge(c.y, y);
        c.clauses.push_back(quoted(file_of(r, file)) + " using " + using_style + " lc rgb " +
                            quoted(arch_colour(r.architecture)) + " title " + quoted(r.architecture + suffix));
    }
    return c;
}

std::string plot_line(const std::vector<std::string>& clauses) {
    std::string out = "plot ";
    for (std::size_t i = 0; i < clauses.size(); ++i) out += (i ? ", \\\n     " : "") + clauses[i];
    return out + "\n";
}

std::optional<Script> path_plot(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    Script s({"path", "Tool path over the programmed path", "X [mm]", "Y [mm]"});
    std::vector<std::string> clauses;
    const PlotRun& first = runs.front();
    if (column_range(out_dir / file_of(first, "program.dat"), 1).rows > 0) {
        clauses.push_back(quoted(file_of(first, "program.dat")) + " using 1:2 with lines lw 4 lc rgb " +
                          quoted(kProgramColour) + " title 'programmed'");
    }
    if (column_range(out_dir / file_of(first, "rapids.dat"), 1).rows > 0) {
        clauses.push_back(quoted(file_of(first, "rapids.dat")) + " using 1:2 with lines lw 2 dt 2 lc rgb " +
                          quoted(kProgramColour) + " title 'programmed rapids'");
    }
    const Curves tools = curves(runs, out_dir, "tool.dat", 2, "2:3 with lines lw 1.5");
    if (tools.clauses.empty()) return std::nullopt;
    clauses.insert(clauses.end(), tools.clauses.begin(), tools.clauses.end());

    // The zoom: around the sample of largest contour error over every run, wide enough to show the deviation and
    // the path on both sides of it, at most an eighth of the job's extent.
    const nlohmann::json* worst = nullptr;
    std::string worst_arch;
    double extent_mm = 1.0;
    for (const PlotRun& r : runs) {
        extent_mm = std::max(extent_mm, r.meta.value("program_extent_mm", 0.0));
        const nlohmann::json& w = r.meta["worst_contour"];
        if (!w.is_null() && (worst == nullptr || w["contour_um"] > (*worst)["contour_um"])) {
            worst = &w;
            worst_arch = r.architecture;
        }
    }
    std::ostringstream body;
    body << header(s.plot) << "set size ratio -1\nset key outside top center horizontal\n";
    if (worst == nullptr) {
        body << plot_line(clauses);
        s.body = body.str();
        return s;
    }
    const double err_mm = (*worst)["contour_um"].get<double>() / 1000.0;
    const double half = std::clamp(3.0 * err_mm, 0.02, extent_mm / 8.0);
    const double x = (*worst)["x_mm"].get<double>();
    const double y = (*worst)["y_mm"].get<double>();
    body << "set multiplot\nset origin 0,0\nset size 0.64,1\n"
         << fmt::format(
                FMT_STRING("set object 1 rect from {:g},{:g} to {:g},{:g} front fillstyle empty border lc rgb 'black' "
                           "lw 1.5\n"),
                x - half, y - half, x + half, y + half)
         << plot_line(clauses) << "unset object 1\nset origin 0.63,0.12\nset size 0.37,0.8\nunset key\n"
         << "set title "
         << quoted("largest cut error: " + worst_arch + fmt::format(FMT_STRING(", {:.1f} um"), err_mm * 1000.0)) << "\n"
         << fmt::format(FMT_STRING("set xrange [{:g}:{:g}]\nset yrange [{:g}:{:g}]\n"), x - half, x + half, y - half,
                        y + half)
         << "set xtics rotate by -30\n"
         << plot_line(clauses) << "unset multiplot\n";
    s.body = body.str();
    return s;
}

std::optional<Script> simple_plot(const std::vector<PlotRun>& runs, const fs::path& out_dir, Plot plot,
                                  const std::string& file, int ycol, const std::string& using_style,
                                  const std::string& extra = "") {
    const Curves c = curves(runs, out_dir, file, ycol, using_style);
    if (c.clauses.empty()) return std::nullopt;
    Script s(std::move(plot));
    s.body = header(s.plot) + extra + yrange_for(c.y) + plot_line(c.clauses);
    return s;
}

// Errors that differ by orders of magnitude between runs (millimetres on one, micrometres on another) share a
// log axis, floored at 0.01 um so that exact runs stay on the plot.
constexpr double kLogFloorUm = 0.01;
constexpr double kLogSpan = 20.0;

std::optional<Script> error_plot(const std::vector<PlotRun>& runs, const fs::path& out_dir, Plot plot, int xcol,
                                 int ycol) {
    double lo_max = 1e300;
    double hi_max = 0.0;
    for (const PlotRun& r : runs) {
        const ColumnRange y = column_range(out_dir / file_of(r, "tool.dat"), ycol);
        if (y.rows == 0) continue;
        lo_max = std::min(lo_max, std::max(y.hi, kLogFloorUm));
        hi_max = std::max(hi_max, y.hi);
    }
    const bool log = hi_max > kLogSpan * lo_max;
    const std::string y =
        log ? fmt::format(FMT_STRING("(${0} > {1:g} ? ${0} : {1:g})"), ycol, kLogFloorUm) : std::to_string(ycol);
    const std::string extra = log ? "set logscale y\nset format y '%g'\n" : "";
    return simple_plot(runs, out_dir, std::move(plot), "tool.dat", ycol,
                       std::to_string(xcol) + ":" + y + " with lines lw 1.2", extra);
}

std::optional<Script> velocity_plot(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    Script s({"velocity", "Commanded and carriage path velocity", "time [s]", "path velocity [mm/s]"});
    const Curves commanded = curves(runs, out_dir, "velocity.dat", 2, "1:2 with lines dt 2 lw 2", " commanded");
    const Curves carriage = curves(runs, out_dir, "velocity.dat", 3, "1:3 with lines lw 1", " carriage");
    if (commanded.clauses.empty()) return std::nullopt;
    std::vector<std::string> clauses = commanded.clauses;
    clauses.insert(clauses.end(), carriage.clauses.begin(), carriage.clauses.end());
    s.body = header(s.plot) + "set key outside bottom center horizontal\n" +
             yrange_for(merge(commanded.y, carriage.y)) + plot_line(clauses);
    return s;
}

// One panel per run: a bar per gap of the job, between and inside the programmed moves in job order (a move's gaps
// side by side, the one that leads into it marked), stacked by cause where the run reports the causes.
std::optional<Script> dead_time_plot(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    Script s({"dead_time", "Dead time between and inside programmed moves",
              "gap [number, in job order: each move's gaps side by side]", "dead time [ms]"});
    bool any = false;
    std::ostringstream body;
    body << "reset\nset multiplot layout " << runs.size() << ",1 title " << quoted(s.plot.title) << "\n";
    for (const PlotRun& r : runs) {
        const std::string file = file_of(r, "dead_time.dat");
        const ColumnRange total = column_range(out_dir / file, 4);
        body << "set title " << quoted(r.architecture + fmt::format(FMT_STRING(": {} gaps"), total.rows))
             << "\nset xlabel " << quoted(s.plot.xlabel) << "\nset ylabel " << quoted(s.plot.ylabel)
             << "\nset grid ytics\nset key outside right top\nset style fill solid 0.9 border -1\nset boxwidth 0.8\n"
             << "set yrange [0:*]\n";
        if (total.rows == 0) {
            body << "set label 1 'no dead time' at graph 0.5,0.5 center\nset xrange [0:1]\n"
                 << "set yrange [0:1]\nplot NaN notitle\nunset label 1\nset xrange [*:*]\n";
            continue;
        }
        any = true;
        if (total.lo == total.hi)
            body << fmt::format(FMT_STRING("set yrange [0:{:g}]\n"), total.hi > 0 ? 1.2 * total.hi : 1.0);
        body << fmt::format(FMT_STRING("set xrange [0:{}]\n"), total.rows + 1);
        const std::vector<std::string> causes = r.meta.value("causes", std::vector<std::string>{});
        std::vector<std::string> clauses;
        // Stacked bars: each cause's bar reaches the sum of it and the causes before it, drawn tallest first.
        for (std::size_t k = causes.size(); k-- > 0;) {
            std::string sum;
            for (std::size_t j = 0; j <= k; ++j) sum += (j ? "+$" : "$") + std::to_string(5 + j);
            clauses.push_back(quoted(file) + " using 1:(" + sum + ") with boxes lc rgb " +
                              quoted(kCauseColours[k % std::size(kCauseColours)]) + " title " + quoted(causes[k]));
        }
        // A clause with no row of its kind would leave gnuplot warning about a file with no valid points.
        const bool inside = r.meta.value("gaps_inside_moves", 0) > 0;
        const bool between = r.meta.value("gaps_between_moves", 0) > 0;
        if (causes.empty() && inside) {
            clauses.push_back(quoted(file) + " using 1:($3 == 1 ? $4 : NaN) with boxes lc rgb " +
                              quoted(kInsideColour) + " title 'inside moves'");
        }
        if (causes.empty() && between) {
            clauses.push_back(quoted(file) + " using 1:($3 == 0 ? $4 : NaN) with boxes lc rgb " +
                              quoted(arch_colour(r.architecture)) + " title 'between moves'");
        }
        if (!causes.empty() && between && inside) {
            clauses.push_back(quoted(file) +
                              " using 1:($3 == 0 ? $4 : NaN) with points pt 9 ps 0.8 lc rgb 'black' title "
                              "'between moves (each starts a move)'");
        }
        body << plot_line(clauses) << "set yrange [*:*]\nset xrange [*:*]\n";
    }
    if (!any) return std::nullopt;
    body << "unset multiplot\n";
    s.body = body.str();
    s.height_px = std::max(kHeightPx / 2, kPanelHeightPx * static_cast<int>(runs.size()) + 60);
    return s;
}

// A plot per reported quantity (ArchRun::series): a curve per run and axis, the axes told apart by dash.
std::vector<Script> series_plots(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    std::map<std::string, std::vector<std::string>> clauses;  // by quantity
    std::map<std::string, ColumnRange> ranges;
    for (const PlotRun& r : runs) {
        const std::vector<std::string> axes = r.meta.value("axes", std::vector<std::string>{});
        for (const nlohmann::json& e : r.meta.value("series", nlohmann::json::array())) {
            const std::string file = file_of(r, e["file"].get<std::string>());
            const ColumnRange y = column_range(out_dir / file, 2);
            if (y.rows == 0) continue;
            const std::string quantity = e["quantity"].get<std::string>();
            const std::string axis = e["axis"].get<std::string>();
            const auto dash = std::find(axes.begin(), axes.end(), axis) - axes.begin() + 1;
            ranges[quantity] = merge(ranges[quantity], y);
            clauses[quantity].push_back(quoted(file) + " using 1:2 with steps lw 1.5 dt " + std::to_string(dash) +
                                        " lc rgb " + quoted(arch_colour(r.architecture)) + " title " +
                                        quoted(r.architecture + ", axis " + axis));
        }
    }
    std::vector<Script> out;
    for (const auto& [quantity, list] : clauses) {
        std::string name = "series_";
        for (const char c : quantity.substr(0, quantity.find(" [")))
            name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
        Script s({name, quantity.substr(0, quantity.find(" [")) + " over time", "time [s]", quantity});
        s.body = header(s.plot) + yrange_for(ranges[quantity]) + plot_line(list);
        out.push_back(std::move(s));
    }
    return out;
}

// The plots an architecture draws of its own data (plots/arch_plot.hpp), its script after the common header.
std::vector<Script> arch_plots(const std::vector<PlotRun>& runs) {
    std::vector<Script> out;
    for (const PlotRun& r : runs) {
        for (const nlohmann::json& p : r.meta.value("arch_plots", nlohmann::json::array())) {
            Script s({p["name"].get<std::string>(), p["title"].get<std::string>(), p["xlabel"].get<std::string>(),
                      p["ylabel"].get<std::string>()});
            s.body = header(s.plot) + "data_dir = " + quoted(r.data_dir) + "\n" + p["script"].get<std::string>();
            out.push_back(std::move(s));
        }
    }
    return out;
}

std::vector<Script> scripts(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    std::vector<std::optional<Script>> all;
    all.push_back(path_plot(runs, out_dir));
    all.push_back(
        error_plot(runs, out_dir,
                   {"contour_error", "Contour error along the path", "tool travel [mm]", "contour error [um]"}, 4, 5));
    all.push_back(error_plot(
        runs, out_dir, {"following_error", "Following error over time", "time [s]", "following error [um]"}, 1, 6));
    std::vector<std::string> axes;
    for (const PlotRun& r : runs) {
        for (const std::string& a : r.meta.value("axes", std::vector<std::string>{})) {
            if (std::find(axes.begin(), axes.end(), a) == axes.end()) axes.push_back(a);
        }
    }
    for (const std::string& a : axes) {
        all.push_back(simple_plot(runs, out_dir,
                                  {"step_period_" + a, "STEP period histogram, axis " + a, "STEP period [us]",
                                   "periods of this length [count]"},
                                  "periods_" + a + ".dat", 2, "1:2 with impulses lw 3",
                                  "set logscale x\nset logscale y\nset yrange [0.8:*]\n"));
        all.push_back(simple_plot(runs, out_dir, {"tie_" + a, "STEP TIE over time, axis " + a, "time [s]", "TIE [ns]"},
                                  "tie_" + a + ".dat", 2, "1:2 with points pt 7 ps 0.5"));
    }
    all.push_back(velocity_plot(runs, out_dir));
    all.push_back(dead_time_plot(runs, out_dir));
    std::vector<Script> out;
    for (auto& s : all) {
        if (s) out.push_back(std::move(*s));
    }
    for (Script& s : series_plots(runs, out_dir)) out.push_back(std::move(s));
    for (Script& s : arch_plots(runs)) out.push_back(std::move(s));
    return out;
}

}  // namespace

std::string arch_colour(const std::string& architecture) {
    return find_architecture(architecture, "plot of " + architecture).plot_colour();
}

std::vector<PlotRun> load_plot_runs(const fs::path& out_dir, const std::vector<std::string>& architectures) {
    std::vector<PlotRun> runs;
    for (const std::string& a : architectures) {
        const std::string data_dir = "data/" + a;
        std::ifstream in(out_dir / data_dir / "meta.json");
        if (!in) continue;  // a run refused before simulating wrote no data
        runs.push_back({a, data_dir, nlohmann::json::parse(in)});
    }
    return runs;
}

std::vector<Plot> render_plots(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    std::vector<Plot> plots;
    if (runs.empty()) return plots;
    fs::create_directories(out_dir / "data");
    std::ofstream all(out_dir / "data" / "plots.gp");
    if (!all) throw std::runtime_error("cannot write " + (out_dir / "data" / "plots.gp").string());
    all << "# Renders every plot: gnuplot data/plots.gp, from the folder that holds it.\n";
    nlohmann::json list = nlohmann::json::array();
    for (const Script& s : scripts(runs, out_dir)) {
        const std::string script = "data/" + s.plot.name + ".gp";
        std::ofstream out(out_dir / script);
        out << s.body;
        all << "set terminal svg size " << kWidthPx << ',' << s.height_px
            << " dynamic noenhanced font 'sans,13' background rgb 'white'\nset output " << quoted(s.plot.name + ".svg")
            << "\nload " << quoted(script) << "\nunset output\n"
            << "set terminal pngcairo size " << kWidthPx << ',' << s.height_px
            << " noenhanced font 'sans,10' background rgb 'white'\nset output " << quoted(s.plot.name + ".png")
            << "\nload " << quoted(script) << "\nunset output\n";
        plots.push_back(s.plot);
        list.push_back({{"name", s.plot.name},
                        {"title", s.plot.title},
                        {"xlabel", s.plot.xlabel},
                        {"ylabel", s.plot.ylabel},
                        {"files", {s.plot.name + ".svg", s.plot.name + ".png"}}});
    }
    all.close();
    std::ofstream(out_dir / "plots.json") << list.dump(2) << '\n';
    int code = 0;
    try {
        code = run_child({"gnuplot", "data/plots.gp"}, out_dir.string());
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string(e.what()) + " (the plots need gnuplot: apt-get install gnuplot-nox)");
    }
    if (code != 0) throw std::runtime_error("gnuplot failed on " + (out_dir / "data" / "plots.gp").string());
    return plots;
}

}  // namespace cnc::sim
