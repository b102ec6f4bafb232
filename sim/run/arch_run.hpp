// What an architecture's system hands back after its simulation: the measured traces for the metrics, and its
// own report section (link, host, controller details) with its warnings.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/warning.hpp"
#include "metrics/metrics.hpp"
#include "metrics/run_input.hpp"
#include "output/gtkw_save.hpp"
#include "plots/arch_plot.hpp"

namespace cnc::sim {

// Where one dead-time gap goes, for an architecture that knows (seed 000's stop-and-wait hand-overs): the gap from
// one executed piece to the next, between programmed moves or inside one.
struct GapCauses {
    std::size_t after_piece = 0;                           // index of the piece the gap follows (RunInput::moves)
    std::vector<std::pair<std::string, double>> parts_ms;  // cause and its share, ms; the parts add up to the gap
};

// A level of a series that means something to the reader (a limit, a threshold): drawn across its plot, labelled.
struct SeriesMark {
    double value = 0.0;  // in the series' unit
    std::string label;
};

// A quantity a model reports over time beyond the edges and tool samples, e.g. the dynamic mechanics' load angle.
struct TimeSeries {
    std::string quantity;  // what the plot is titled with, unit in brackets: "load angle [deg]"
    std::string axis;      // x, y
    std::vector<std::pair<TimePs, double>> points;
    std::vector<SeriesMark> marks;
};

struct ArchRun {
    metrics::RunInput input;                     // empty logs and samples when the metrics streamed (`metrics` set)
    std::optional<metrics::RunMetrics> metrics;  // computed by the system itself; else run.cpp computes them from input
    // Other recorded pins (busy, UART lines), by name; kept only with the whole logs (Scenario::keep_run_input)
    // where a long job's lines would grow with it.
    std::map<std::string, EdgeLog> lines;
    nlohmann::json details = nlohmann::json::object();  // architecture section of the JSON report
    std::string details_text;                           // the same, for the summary
    // The clock its logic ran on (report["clock"], docs/metrics.md "Clocks") and its summary line; null and empty
    // for an architecture without one.
    nlohmann::json clock;
    std::string clock_text;
    std::vector<Warning> warnings;  // grouped by kind in the reports (run.cpp)
    // Empty: the architecture reports no split (the plots draw whole gaps); filled only for the plots
    // (Scenario::keep_run_input).
    std::vector<GapCauses> gap_causes;
    std::vector<TimeSeries> series;  // plotted per quantity when present (sim/plots/plot_data.hpp)
    // The architecture's own plots (sim/plots/arch_plot.hpp); filled only for the plots (Scenario::keep_run_input).
    std::vector<ArchPlot> plots;
    bool ok = true;
    std::string failure;
    double estimated_s = 0.0;  // the job's estimate and the simulated-time limit the run had (run/simulate.hpp)
    double max_sim_s = 0.0;
    // What the VCD holds, for its gtkwave save file, when the run wrote one; and where the save file zooms: the
    // first move, which an architecture without programmed moves sets (run_scenario sets the others').
    std::optional<TraceLayout> trace;
    std::optional<TimeSpan> first_move;
};

}  // namespace cnc::sim
