// index.html of `cncsim compare --out DIR`: one page that works offline (no script, no external font or style;
// images are the plot files next to it): the machine and job, the table, every plot, each architecture's warnings.
#pragma once
#include <string>
#include <vector>

#include "compare/compare.hpp"
#include "plots/plot_render.hpp"

namespace cnc::sim {

struct HtmlJob {
    std::string scenario_file;
    std::string scenario_text;           // the scenario file as written
    std::vector<std::string> overrides;  // --set key=value
    std::string job_file;
    std::string job_text;  // the G-code (its head on long jobs)
    std::size_t job_lines = 0;
};

// Each column's colour in the plots and on the page: its architecture's, or for several variants of one
// architecture a colour of its own around it (variant_colour).
std::vector<std::string> column_colours(const std::vector<CompareColumn>& columns);

std::string html_report(const Comparison& comparison, const std::vector<Plot>& plots, const HtmlJob& job);

}  // namespace cnc::sim
