#include "plots/arch_plot.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace cnc::sim {

namespace {

void write_table(const PlotTable& t, const std::filesystem::path& dir) {
    const std::filesystem::path file = dir / t.file;
    std::ofstream out(file);
    if (!out) throw std::runtime_error("cannot write " + file.string());
    out << "# " << t.columns << '\n';
    for (std::size_t b = 0; b < t.blocks.size(); ++b) {
        if (b > 0) out << "\n\n";
        for (const std::vector<double>& row : t.blocks[b]) {
            for (std::size_t c = 0; c < row.size(); ++c) {
                char buf[32];
                std::snprintf(buf, sizeof buf, "%.9g", row[c]);
                out << (c ? " " : "") << buf;
            }
            out << '\n';
        }
    }
}

}  // namespace

nlohmann::json write_arch_plots(const std::vector<ArchPlot>& plots, const std::filesystem::path& dir) {
    nlohmann::json list = nlohmann::json::array();
    for (const ArchPlot& p : plots) {
        for (const PlotTable& t : p.tables) write_table(t, dir);
        list.push_back(
            {{"name", p.name}, {"title", p.title}, {"xlabel", p.xlabel}, {"ylabel", p.ylabel}, {"script", p.script}});
    }
    return list;
}

}  // namespace cnc::sim
