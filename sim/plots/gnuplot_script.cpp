#include "plots/gnuplot_script.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace cnc::sim::gp {

namespace fs = std::filesystem;

std::vector<ColumnRange> column_ranges(const fs::path& file, int columns) {
    std::vector<ColumnRange> ranges(static_cast<std::size_t>(columns));
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        for (ColumnRange& r : ranges) {
            double v = 0.0;
            if (!(fields >> v)) break;
            r.lo = r.rows == 0 ? v : std::min(r.lo, v);
            r.hi = r.rows == 0 ? v : std::max(r.hi, v);
            ++r.rows;
        }
    }
    return ranges;
}

ColumnRange column_range(const fs::path& file, int column) {
    return column_ranges(file, column).back();
}

ColumnRange merge(ColumnRange a, const ColumnRange& b) {
    if (b.rows == 0) return a;
    if (a.rows == 0) return b;
    return {a.rows + b.rows, std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

std::vector<std::vector<double>> read_rows(const fs::path& file, int columns) {
    std::vector<std::vector<double>> rows;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        std::vector<double> row(static_cast<std::size_t>(columns));
        for (double& v : row) fields >> v;
        if (fields) rows.push_back(std::move(row));
    }
    return rows;
}

std::string quoted(const std::string& s) {
    std::string out = "'";
    for (const char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

std::string quoted_lines(const std::vector<std::string>& lines) {
    std::string out = "\"";
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (i > 0) out += "\\n";
        for (const char c : lines[i]) {
            if (c == '"' || c == '\\') out += '\\';
            out += c;
        }
    }
    return out + "\"";
}

std::string file_of(const PlotRun& r, const std::string& name) {
    return r.data_dir + "/" + name;
}

std::string header(const Plot& p) {
    return "reset\nset title " + quoted(p.title) + "\nset xlabel " + quoted(p.xlabel) + "\nset ylabel " +
           quoted(p.ylabel) + "\nset grid\nset key outside top center horizontal box\n";
}

std::string yrange_for(const ColumnRange& r) {
    if (r.rows == 0 || r.lo != r.hi) return "";
    return fmt::format(FMT_STRING("set yrange [{:g}:{:g}]\n"), r.lo - 1.0, r.hi + 1.0);
}

Curves curves(const std::vector<PlotRun>& runs, const fs::path& out_dir, const std::string& file, int ycol,
              const std::string& using_style, const std::string& suffix) {
    Curves c;
    for (const PlotRun& r : runs) {
        const ColumnRange y = column_range(out_dir / file_of(r, file), ycol);
        if (y.rows == 0) continue;
        c.y = merge(c.y, y);
        c.clauses.push_back(quoted(file_of(r, file)) + " using " + using_style + " lc rgb " + quoted(r.colour) +
                            " title " + quoted(r.label + suffix));
    }
    return c;
}

std::string plot_line(const std::vector<std::string>& clauses) {
    std::string out = "plot ";
    for (std::size_t i = 0; i < clauses.size(); ++i) out += (i ? ", \\\n     " : "") + clauses[i];
    return out + "\n";
}

std::string margins(const PanelBox& box, int height_px) {
    const auto x = [](int px) { return static_cast<double>(px) / kWidthPx; };
    const auto y = [height_px](int px) { return 1.0 - static_cast<double>(px) / height_px; };
    return fmt::format(FMT_STRING("set lmargin at screen {:.5f}\nset rmargin at screen {:.5f}\n"
                                  "set tmargin at screen {:.5f}\nset bmargin at screen {:.5f}\n"),
                       x(box.left_px), x(box.right_px), y(box.top_px), y(box.bottom_px));
}

}  // namespace cnc::sim::gp
