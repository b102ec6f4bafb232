// The plot data files of a synthetic run whose every figure is known: two 100-step X moves at F1200 on the seed 000
// machine (160 steps/mm: a STEP every 312.5 us), 4 ms apart, the carriage on the line at every step.
#include "plots/plot_data.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "../metrics/metrics_test_util.hpp"
#include "metrics/metrics.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cnc;
using namespace cnc::metrics::test;

constexpr TimePs kPeriodPs = 312'500'000;  // 60 / (1200 mm/min x 160 steps/mm)
constexpr TimePs kGapPs = 4 * kPsPerMs;
constexpr int kSteps = 100;

std::vector<std::vector<double>> rows(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::vector<double>> out;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream f(line);
        std::vector<double> r;
        for (double v; f >> v;) r.push_back(v);
        out.push_back(r);
    }
    return out;
}

struct PlotData : ::testing::Test {
    fs::path dir =
        fs::temp_directory_path() /
        ("cncsim-plot_data_test-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
         std::to_string(getpid()));
    void TearDown() override { fs::remove_all(dir); }

    nlohmann::json meta() const {
        std::ifstream in(dir / "meta.json");
        return nlohmann::json::parse(in);
    }

    // `change` edits the run before its metrics and plot data are computed. Returns the metrics' contour error max.
    std::optional<double> write(const std::function<void(sim::ArchRun&)>& change = {}) {
        sim::ArchRun run;
        const std::vector<TimePs> first = grid(kPsPerMs, kPeriodPs, kSteps);
        const TimePs second_start = first.back() + kGapPs;
        std::vector<TimePs> rises = first;
        for (const TimePs t : grid(second_start, kPeriodPs, kSteps)) rises.push_back(t);
        metrics::RunInput& in = run.input;
        in.axes = {axis(rises, "x")};
        in.axes[0].steps_per_mm = 160.0;
        const double move_mm = kSteps * kMicrostepMm;
        in.moves = {
            line_move(0, {0, 0}, {move_mm, 0}, 1200.0, 0, first.back() + kPsPerUs),
            line_move(1, {move_mm, 0}, {2 * move_mm, 0}, 1200.0, second_start - kPsPerUs, rises.back() + kPeriodPs)};
        for (std::size_t k = 0; k < rises.size(); ++k) {
            in.tool.push_back({rises[k], {static_cast<double>(k + 1) * kMicrostepMm, 0.0}});
        }
        in.t_job_end_ps = rises.back() + kPeriodPs;
        run.gap_causes = {{0, {{"wire", 1.5}, {"host", 2.5}}}};
        run.series = {{"load angle [deg]", "x", {{kPsPerMs, 1.0}, {2 * kPsPerMs, 2.0}}, {{90.0, "pull-out"}}}};
        if (change) change(run);
        const metrics::RunMetrics m = metrics::compute_metrics(in);
        sim::write_plot_data("fpga-uart", run, m, dir);
        return m.path.contour_max_um;
    }
};

}  // namespace

TEST_F(PlotData, PeriodHistogramCountsThePeriodsWithinEachRun) {
    write();
    const auto periods = rows(dir / "periods_x.dat");
    ASSERT_EQ(periods.size(), 1U);  // the 4 ms gap is between runs, not a period
    EXPECT_DOUBLE_EQ(periods[0][0], 312.5);
    EXPECT_EQ(periods[0][1], 2.0 * (kSteps - 1));
}

TEST_F(PlotData, DeadTimeRowsCarryTheGapAndItsCauses) {
    write();
    const auto gaps = rows(dir / "dead_time.dat");
    ASSERT_EQ(gaps.size(), 1U);
    // Gap 1, leading into move 2, between moves: 4 ms = 1.5 + 2.5.
    EXPECT_EQ(gaps[0], (std::vector<double>{1, 2, 0, 4.0, 1.5, 2.5}));
    const nlohmann::json m = meta();
    EXPECT_EQ(m.at("causes"), nlohmann::json({"wire", "host"}));
    EXPECT_EQ(m.at("series").at(0).at("quantity"), "load angle [deg]");
    EXPECT_EQ(m.at("series").at(0).at("marks"), nlohmann::json::parse(R"([{"value": 90.0, "label": "pull-out"}])"));
    EXPECT_EQ(rows(dir / m.at("series").at(0).at("file").get<std::string>()).size(), 2U);
}

// Move 1 (line 1) made a rapid with its 51st sample 20 um off the line, move 2 (line 2) with its 51st 10 um off:
// the zoom looks at the cut's 10 um, and the worst of all is the rapid's 20 um, the report's contour error max.
TEST_F(PlotData, ZoomPointIsTheWorstCutAndTheWorstOfAllIsTheReportsMax) {
    const std::optional<double> contour_max_um = write([](sim::ArchRun& run) {
        run.input.moves[0].rapid = true;
        run.input.tool[50].pos.y_mm += 0.020;
        run.input.tool[kSteps + 50].pos.y_mm += 0.010;
    });
    const nlohmann::json cut = meta().at("worst_contour");
    EXPECT_NEAR(cut.at("contour_um").get<double>(), 10.0, 1e-6);
    EXPECT_EQ(cut.at("line"), 2);
    EXPECT_EQ(cut.at("rapid"), false);
    EXPECT_NEAR(cut.at("x_mm").get<double>(), (kSteps + 51) * kMicrostepMm, 1e-12);
    EXPECT_NEAR(cut.at("y_mm").get<double>(), 0.010, 1e-12);
    const nlohmann::json all = meta().at("contour_max");
    EXPECT_NEAR(all.at("contour_um").get<double>(), 20.0, 1e-6);
    EXPECT_EQ(all.at("line"), 1);
    EXPECT_EQ(all.at("rapid"), true);
    ASSERT_TRUE(contour_max_um.has_value());
    EXPECT_NEAR(*contour_max_um, 20.0, 1e-6);
}

// A 20 s job whose carriage moves in bursts, 8 steps 100 us apart every 10 ms: the grid is 20 s / 2000 = 10 ms,
// and a window of the grid's step holds one burst wherever it falls, 8 / 160 mm in 10 ms = 5 mm/s at every row
// (a 5 ms window would hold a burst or none: 10 or 0 mm/s).
TEST_F(PlotData, CarriageSpeedOfALongJobIsTheMeanOverTheGridStep) {
    constexpr TimePs kBurstPs = 10 * kPsPerMs;
    constexpr int kBursts = 2000;
    write([](sim::ArchRun& run) {
        metrics::RunInput& in = run.input;
        std::vector<TimePs> rises;
        for (int b = 0; b < kBursts; ++b) {
            for (const TimePs t : grid(b * kBurstPs + kPsPerMs, 100 * kPsPerUs, 8)) rises.push_back(t);
        }
        in.axes = {axis(rises, "x")};
        in.axes[0].steps_per_mm = 160.0;
        in.t_job_start_ps = 0;
        in.t_job_end_ps = kBursts * kBurstPs;
        const double length_mm = static_cast<double>(rises.size()) * kMicrostepMm;
        in.moves = {line_move(0, {0, 0}, {length_mm, 0}, 300.0, 0, in.t_job_end_ps)};
        in.tool.clear();
        for (std::size_t k = 0; k < rises.size(); ++k) {
            in.tool.push_back({rises[k], {static_cast<double>(k + 1) * kMicrostepMm, 0.0}});
        }
        run.gap_causes.clear();
    });
    const auto velocity = rows(dir / "velocity.dat");
    ASSERT_EQ(velocity.size(), static_cast<std::size_t>(kBursts) + 1);
    // The first and last rows' windows reach past the job's ends.
    for (std::size_t i = 1; i + 1 < velocity.size(); ++i) ASSERT_NEAR(velocity[i][2], 5.0, 1e-9) << "row " << i;
}

// An architecture's own plot (ArchRun::plots): its table in blocks gnuplot reads as `index 0`, `index 1` (two blank
// lines apart), and its labels and script in meta.json for the renderer.
TEST_F(PlotData, AnArchitecturesOwnPlotWritesItsTableInBlocks) {
    sim::ArchRun run;
    sim::ArchPlot plot;
    plot.name = "own";
    plot.title = "Own";
    plot.xlabel = "x [mm]";
    plot.ylabel = "y [um]";
    plot.tables.push_back({"own.dat", "x_mm y_um", {{{0.0, 1.5}, {0.25, -2.0}}, {{1.0, 3.0}}}});
    plot.script = "plot data_dir.'/own.dat' index 1 using 1:2\n";
    run.plots.push_back(plot);
    sim::write_plot_data("fpga-uart", run, metrics::compute_metrics(run.input), dir);
    std::ifstream table(dir / "own.dat");
    std::stringstream text;
    text << table.rdbuf();
    EXPECT_EQ(text.str(), "# x_mm y_um\n0 1.5\n0.25 -2\n\n\n1 3\n");
    std::ifstream meta_in(dir / "meta.json");
    const nlohmann::json own = nlohmann::json::parse(meta_in).at("arch_plots").at(0);
    EXPECT_EQ(own.at("name"), "own");
    EXPECT_EQ(own.at("ylabel"), "y [um]");
    EXPECT_EQ(own.at("script"), plot.script);
}

TEST_F(PlotData, ToolRowsFollowTheLineAtTheCommandedSpeed) {
    write();
    const auto tool = rows(dir / "tool.dat");
    ASSERT_EQ(tool.size(), 2U * kSteps);
    EXPECT_NEAR(tool.back()[3], 2 * kSteps * kMicrostepMm - kMicrostepMm, 1e-9);  // travel from the first sample
    for (const auto& r : tool) EXPECT_NEAR(r[4], 0.0, 1e-9);                      // contour: on the line
    // Inside move 0 (t = 10 ms) both the command and the carriage run at F1200 = 20 mm/s; the carriage's 5 ms window
    // holds 16 steps of 1/160 mm: 0.1 mm / 5 ms.
    for (const auto& r : rows(dir / "velocity.dat")) {
        if (std::abs(r[0] - 0.010) > 1e-9) continue;
        EXPECT_DOUBLE_EQ(r[1], 20.0);
        EXPECT_NEAR(r[2], 20.0, 1e-9);
    }
    EXPECT_NEAR(meta().at("program_extent_mm").get<double>(), 2 * kSteps * kMicrostepMm, 1e-12);
}
