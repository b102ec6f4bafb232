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
#include <nlohmann/json.hpp>

#include "architectures/catalog.hpp"
#include "compare/spawn.hpp"
#include "plots/gnuplot_script.hpp"
#include "plots/path_plot.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

using gp::column_range;
using gp::column_ranges;
using gp::ColumnRange;
using gp::Curves;
using gp::curves;
using gp::file_of;
using gp::header;
using gp::merge;
using gp::plot_line;
using gp::quoted;
using gp::Script;
using gp::yrange_for;

// Dead-time causes, in the order the architectures report them; the palette avoids the architecture colours.
constexpr const char* kCauseColours[] = {"#e69f00", "#56b4e9", "#f0e442", "#cc79a7", "#999999",
                                         "#000000", "#882255", "#44aa99", "#ddcc77", "#117733"};
// The gaps inside a programmed move (between its pieces) where the run reports no causes.
constexpr const char* kInsideColour = "#999999";
constexpr int kPanelHeightPx = 260;
// Beyond this many gaps in a panel a bar is a few pixels wide, and a black border on each would paint it black.
constexpr std::size_t kMaxBorderedBars = 100;
constexpr int kPanelFramePx = 110;  // a panel's title, tic labels and axis label
constexpr int kKeyRowPx = 20;       // a key row in the SVG's 13 pt
// The panels of one plot share their left and right edges, so that their axes line up whatever each one's key
// holds; the keys go right of them.
constexpr const char* kPanelMargins = "set lmargin at screen 0.09\nset rmargin at screen 0.77\n";

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

// One panel per run on the same axes, the commanded path speed (dashed, in the programmed path's colour) over the
// carriage's: the curves of several runs on one axis tangle as soon as a job has more than a few moves.
std::optional<Script> velocity_plot(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    Script s({"velocity", "Commanded and carriage path velocity", "time [s]", "path velocity [mm/s]"});
    std::vector<const PlotRun*> drawn;
    ColumnRange t, v;
    for (const PlotRun& r : runs) {
        const fs::path file = out_dir / file_of(r, "velocity.dat");
        const std::vector<ColumnRange> columns = column_ranges(file, 3);  // time, commanded, carriage
        if (columns[0].rows == 0) continue;
        drawn.push_back(&r);
        t = merge(t, columns[0]);
        v = merge(merge(v, columns[1]), columns[2]);
    }
    if (drawn.empty()) return std::nullopt;
    std::ostringstream body;
    body << "reset\nset multiplot layout " << drawn.size() << ",1 title " << quoted(s.plot.title) << "\n"
         << kPanelMargins
         << fmt::format(FMT_STRING("set xrange [{:g}:{:g}]\nset yrange [{:g}:{:g}]\n"), t.lo,
                        t.hi > t.lo ? t.hi : t.lo + 1.0, std::min(0.0, v.lo), v.hi > 0.0 ? 1.05 * v.hi : 1.0)
         << "set xlabel " << quoted(s.plot.xlabel) << "\nset ylabel " << quoted(s.plot.ylabel)
         << "\nset grid\nset key outside right top vertical box\n";
    for (const PlotRun* r : drawn) {
        const std::string file = quoted(file_of(*r, "velocity.dat"));
        body << "set title " << quoted(r->label) << "\n"
             << plot_line({file + " using 1:3 with lines lw 1 lc rgb " + quoted(r->colour) + " title 'carriage'",
                           file + " using 1:2 with lines lw 1.5 dt 2 lc rgb " + quoted(gp::kProgramColour) +
                               " title 'commanded'"});
    }
    body << "unset multiplot\n";
    s.body = body.str();
    s.height_px = std::max(gp::kHeightPx / 2, kPanelHeightPx * static_cast<int>(drawn.size()) + 60);
    return s;
}

// One panel per run: a bar per gap of the job, between and inside the programmed moves in job order (a move's gaps
// side by side, the one that leads into it marked), stacked by cause where the run reports the causes.
std::optional<Script> dead_time_plot(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    Script s({"dead_time", "Dead time between and inside programmed moves",
              "gap [number, in job order: each move's gaps side by side]", "dead time [ms]"});
    bool any = false;
    int key_rows = 0;
    std::ostringstream body;
    body << "reset\nset multiplot layout " << runs.size() << ",1 title " << quoted(s.plot.title) << "\n"
         << kPanelMargins;
    for (const PlotRun& r : runs) {
        const std::string file = file_of(r, "dead_time.dat");
        const ColumnRange total = column_range(out_dir / file, 4);
        body << "set title " << quoted(r.label + fmt::format(FMT_STRING(": {} gaps"), total.rows)) << "\nset xlabel "
             << quoted(s.plot.xlabel) << "\nset ylabel " << quoted(s.plot.ylabel)
             << "\nset grid ytics\nset key outside right top\nset style fill solid 0.9 "
             << (total.rows > kMaxBorderedBars ? "noborder" : "border -1") << "\nset boxwidth 0.8\nset yrange [0:*]\n";
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
            clauses.push_back(quoted(file) + " using 1:($3 == 0 ? $4 : NaN) with boxes lc rgb " + quoted(r.colour) +
                              " title 'between moves'");
        }
        if (!causes.empty() && between && inside) {
            clauses.push_back(quoted(file) +
                              " using 1:($3 == 0 ? $4 : NaN) with points pt 9 ps 0.8 lc rgb 'black' title "
                              "'between moves'");
        }
        key_rows = std::max(key_rows, static_cast<int>(clauses.size()));
        body << plot_line(clauses) << "set yrange [*:*]\nset xrange [*:*]\n";
    }
    if (!any) return std::nullopt;
    body << "unset multiplot\n";
    s.body = body.str();
    // A panel as tall as its key: a key taller than the panel wraps into a second column over the bars.
    const int panel_px = std::max(kPanelHeightPx, kPanelFramePx + kKeyRowPx * key_rows);
    s.height_px = std::max(gp::kHeightPx / 2, panel_px * static_cast<int>(runs.size()) + 60);
    return s;
}

// A series' marks (TimeSeries::marks) as labelled lines across the plot, the y range taking them in with room
// for their labels over them.
std::string marks_of(const std::map<double, std::string>& marks, ColumnRange y) {
    if (marks.empty()) return yrange_for(y);
    std::string out;
    int tag = 1;
    for (const auto& [value, label] : marks) {
        y = merge(y, {1, value, value});
        out += fmt::format(FMT_STRING("set arrow {0} from graph 0, first {1:g} to graph 1, first {1:g} nohead front "
                                      "lc rgb 'black' lw 1.5 dt 4\nset label {0} {2} at graph 0.01, first {1:g} left "
                                      "offset 0,0.7 front\n"),
                           tag, value, quoted(label));
        ++tag;
    }
    const double span = y.hi > y.lo ? y.hi - y.lo : 1.0;
    return out + fmt::format(FMT_STRING("set yrange [{:g}:{:g}]\n"), std::min(y.lo, 0.0), y.hi + 0.08 * span);
}

// A plot per reported quantity (ArchRun::series): a curve per run and axis, the axes told apart by dash.
std::vector<Script> series_plots(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    std::map<std::string, std::vector<std::string>> clauses;  // by quantity
    std::map<std::string, ColumnRange> ranges;
    std::map<std::string, std::map<double, std::string>> marks;  // by quantity: level, label
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
            for (const nlohmann::json& m : e.value("marks", nlohmann::json::array()))
                marks[quantity][m["value"].get<double>()] = m["label"].get<std::string>();
            clauses[quantity].push_back(quoted(file) + " using 1:2 with steps lw 1.5 dt " + std::to_string(dash) +
                                        " lc rgb " + quoted(r.colour) + " title " + quoted(r.label + ", axis " + axis));
        }
    }
    std::vector<Script> out;
    for (const auto& [quantity, list] : clauses) {
        std::string name = "series_";
        for (const char c : quantity.substr(0, quantity.find(" [")))
            name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
        Script s({name, quantity.substr(0, quantity.find(" [")) + " over time", "time [s]", quantity});
        s.body = header(s.plot) + marks_of(marks[quantity], ranges[quantity]) + plot_line(list);
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

namespace {

struct Hsl {
    double h_deg, s, l;
};

Hsl to_hsl(const std::string& hex) {
    double c[3];
    for (int i = 0; i < 3; ++i) c[i] = std::stoi(hex.substr(1 + 2 * i, 2), nullptr, 16) / 255.0;
    const double hi = std::max({c[0], c[1], c[2]});
    const double lo = std::min({c[0], c[1], c[2]});
    const double l = (hi + lo) / 2.0;
    if (hi == lo) return {0.0, 0.0, l};
    const double d = hi - lo;
    const double s = l > 0.5 ? d / (2.0 - hi - lo) : d / (hi + lo);
    double h = hi == c[0]   ? (c[1] - c[2]) / d + (c[1] < c[2] ? 6.0 : 0.0)
               : hi == c[1] ? (c[2] - c[0]) / d + 2.0
                            : (c[0] - c[1]) / d + 4.0;
    return {h * 60.0, s, l};
}

std::string to_hex(Hsl x) {
    const double h = std::fmod(std::fmod(x.h_deg, 360.0) + 360.0, 360.0) / 360.0;
    const double q = x.l < 0.5 ? x.l * (1.0 + x.s) : x.l + x.s - x.l * x.s;
    const double p = 2.0 * x.l - q;
    const auto channel = [&](double t) {
        t = t < 0.0 ? t + 1.0 : t > 1.0 ? t - 1.0 : t;
        const double v = t < 1.0 / 6.0   ? p + (q - p) * 6.0 * t
                         : t < 0.5       ? q
                         : t < 2.0 / 3.0 ? p + (q - p) * (2.0 / 3.0 - t) * 6.0
                                         : p;
        return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
    };
    return fmt::format(FMT_STRING("#{:02x}{:02x}{:02x}"), channel(h + 1.0 / 3.0), channel(h), channel(h - 1.0 / 3.0));
}

// Hue apart per variant, and the widest spread: within it the variants stay near their architecture's colour.
constexpr double kVariantHueStepDeg = 36.0;
constexpr double kVariantHueSpanDeg = 160.0;
// Two lightnesses alternating between neighbours, each lowered where the hue is bright (yellow, cyan) until the
// colour's luma (Rec. 601: 0.299 R + 0.587 G + 0.114 B) is at most its cap, so that a 1 px line shows on white.
constexpr double kVariantDarkL = 0.34;
constexpr double kVariantLightL = 0.52;
constexpr double kDarkLumaCap = 0.36;
constexpr double kLightLumaCap = 0.52;
constexpr double kLightnessStep = 0.01;
constexpr double kMinVariantSaturation = 0.7;
// A colour without hue (the ideal's black): greys from this dark to this light.
constexpr double kGreyDarkL = 0.0;
constexpr double kGreyLightL = 0.5;

}  // namespace

std::string variant_colour(const std::string& base, std::size_t k, std::size_t n) {
    if (n <= 1) return base;
    const double at = static_cast<double>(k) / static_cast<double>(n - 1);  // 0 .. 1
    const Hsl b = to_hsl(base);
    if (b.s < 0.05) return to_hex({0.0, 0.0, kGreyDarkL + (kGreyLightL - kGreyDarkL) * at});
    const double span = std::min(kVariantHueStepDeg * static_cast<double>(n - 1), kVariantHueSpanDeg);
    const bool dark = k % 2 == 0;
    Hsl c{b.h_deg + (at - 0.5) * span, std::max(b.s, kMinVariantSaturation), dark ? kVariantDarkL : kVariantLightL};
    const auto luma = [](const std::string& hex) {
        const auto ch = [&](int i) { return std::stoi(hex.substr(1 + 2 * i, 2), nullptr, 16) / 255.0; };
        return 0.299 * ch(0) + 0.587 * ch(1) + 0.114 * ch(2);
    };
    while (luma(to_hex(c)) > (dark ? kDarkLumaCap : kLightLumaCap)) c.l -= kLightnessStep;
    return to_hex(c);
}

std::vector<PlotRun> load_plot_runs(const fs::path& out_dir, const std::vector<PlotSource>& sources) {
    std::vector<PlotRun> runs;
    for (const PlotSource& s : sources) {
        const std::string data_dir = "data/" + s.file_stem;
        std::ifstream in(out_dir / data_dir / "meta.json");
        if (!in) continue;  // a run refused before simulating wrote no data
        runs.push_back({s.label, s.colour, data_dir, nlohmann::json::parse(in)});
    }
    return runs;
}

std::vector<Plot> render_plots(const std::vector<PlotRun>& runs, const fs::path& out_dir) {
    if (runs.empty()) return {};
    return gp::render_scripts(scripts(runs, out_dir), out_dir);
}

std::vector<Plot> gp::render_scripts(const std::vector<Script>& scripts, const fs::path& out_dir) {
    std::vector<Plot> plots;
    fs::create_directories(out_dir / "data");
    std::ofstream all(out_dir / "data" / "plots.gp");
    if (!all) throw std::runtime_error("cannot write " + (out_dir / "data" / "plots.gp").string());
    all << "# Renders every plot: gnuplot data/plots.gp, from the folder that holds it.\n";
    nlohmann::json list = nlohmann::json::array();
    for (const Script& s : scripts) {
        const std::string script = "data/" + s.plot.name + ".gp";
        std::ofstream out(out_dir / script);
        out << s.body;
        all << "set terminal svg size " << gp::kWidthPx << ',' << s.height_px
            << " dynamic noenhanced font 'sans,13' background rgb 'white'\nset output " << quoted(s.plot.name + ".svg")
            << "\nload " << quoted(script) << "\nunset output\n"
            << "set terminal pngcairo size " << gp::kWidthPx << ',' << s.height_px
            << " noenhanced font 'sans,10' background rgb 'white'\nset output " << quoted(s.plot.name + ".png")
            << "\nload " << quoted(script) << "\nunset output\n";
        plots.push_back(s.plot);
        list.push_back({{"name", s.plot.name},
                        {"title", s.plot.title},
                        {"xlabel", s.plot.xlabel},
                        {"ylabel", s.plot.ylabel},
                        {"files", {s.plot.name + ".svg", s.plot.name + ".png"}}});
        if (!s.panels.empty()) {
            nlohmann::json& panels = list.back()["panels"] = nlohmann::json::array();
            for (const gp::PanelBox& b : s.panels) {
                panels.push_back({{"title", b.title}, {"box_px", {b.left_px, b.top_px, b.right_px, b.bottom_px}}});
            }
        }
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
