#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

#include "common/bad_input.hpp"
#include "metrics/metrics.hpp"
#include "metrics/report/report.hpp"
#include "metrics/vcd/analyze_input.hpp"
#include "metrics/vcd/vcd_writer.hpp"
#include "metrics_test_util.hpp"

namespace cnc::metrics {
namespace {

using test::grid;

constexpr std::int64_t k1ns = 1'000'000;  // fs

VcdContents capture(const std::vector<EdgeLog>& logs, const std::string& extra_vars = "") {
    std::ostringstream vcd;
    write_vcd(vcd, logs, k1ns);
    std::string text = vcd.str();
    text.insert(text.find("$upscope"), extra_vars);
    std::istringstream in(text);
    return read_vcd(in, "cap.vcd");
}

// The message of the BadInput that analyze_input throws.
std::string error_of(const VcdContents& vcd, const AxisSignalNames& names) {
    try {
        (void)analyze_input(vcd, "cap.vcd", {names});
    } catch (const BadInput& e) {
        return e.what();
    }
    return "";
}

TEST(MetricsAnalyze, InputFromVcdSignals) {
    const VcdContents vcd = capture({test::step_log(grid(10'000'000, 312'500'000, 50)), EdgeLog{"dir_x", true, {}}});
    const RunInput run = analyze_input(vcd, "cap.vcd", {{"step_x", "dir_x", "", EnableLevel::ActiveHigh}}, 160.0);
    ASSERT_EQ(run.axes.size(), 1U);
    EXPECT_EQ(run.axes[0].steps_per_mm, 160.0);
    EXPECT_TRUE(run.moves.empty());
    EXPECT_EQ(run.t_job_start_ps, 10'000'000);
    EXPECT_EQ(run.t_job_end_ps, TimePs{10'000'000} + 49 * TimePs{312'500'000} + 2'000'000);
    const RunMetrics m = compute_metrics(run);
    EXPECT_EQ(m.axes[0].net_steps, 50);
    EXPECT_DOUBLE_EQ(*m.axes[0].net_mm, 50.0 / 160.0);
    ASSERT_EQ(m.axes[0].runs.size(), 1U);
    EXPECT_NEAR(*m.axes[0].runs[0].speed_mm_per_min, 3200.0 / 160.0 * 60.0, 1e-9);
    EXPECT_NE(summary_table(m).find("Pulse timing (runs split by period change)"), std::string::npos);
    EXPECT_EQ(to_json(m)["run_split_tolerance"], 0.005);
    // Lead-in, tail and gaps need the job's moves: "-" and null, not a misleading 0.
    EXPECT_NE(summary_table(m).find("Job timing (the span of the traced edges)\n"), std::string::npos);
    EXPECT_NE(summary_table(m).find("-          -\n"), std::string::npos) << summary_table(m);  // lead-in, tail
    EXPECT_NE(summary_table(m).find("between moves     -           -          -         -\n"), std::string::npos)
        << summary_table(m);
    for (const char* field : {"lead_in_ms", "tail_ms", "dead_gaps"}) {
        EXPECT_TRUE(to_json(m)["job"][field].is_null()) << field;
    }
    EXPECT_EQ(analyze_input(vcd, "cap.vcd", {{"step_x", "", "", EnableLevel::ActiveHigh}}).axes[0].dir.edges.size(),
              0U);
    EXPECT_THROW((void)analyze_input(vcd, "cap.vcd", {{"step_x", "dir_x", "", EnableLevel::ActiveHigh}}, 0.0),
                 BadInput);
}

// Each axis is labelled with its STEP signal's name: a lone Y axis is not reported as "x".
TEST(MetricsAnalyze, AxesAreLabelledByTheirStepSignal) {
    EdgeLog step_y = test::step_log(grid(0, 100'000'000, 5));
    step_y.name = "step_y";
    const VcdContents vcd = capture({step_y, EdgeLog{"dir_y", false, {}}});
    const RunInput run = analyze_input(vcd, "cap.vcd", {{"step_y", "dir_y", "", EnableLevel::ActiveHigh}});
    const RunMetrics m = compute_metrics(run);
    EXPECT_EQ(m.axes.at(0).name, "step_y");
    EXPECT_NE(summary_table(m).find("\nstep_y  step_y  dir_y"), std::string::npos) << summary_table(m);
}

// STEP edges while the driver is disabled do not count, as in the atmega run (enabled_steps.hpp).
TEST(MetricsAnalyze, EnableSignalDropsTheStepsOfADisabledDriver) {
    const VcdContents vcd = capture({test::step_log(grid(10'000'000, 100'000'000, 10)), EdgeLog{"dir_x", false, {}},
                                     EdgeLog{"n_enbl_x", true, {{300'000'000, false}, {700'000'000, true}}}});
    const auto rising = [&vcd](const std::string& enable, EnableLevel active) {
        return analyze_input(vcd, "cap.vcd", {{"step_x", "dir_x", enable, active}}).axes[0].step.rising().size();
    };
    EXPECT_EQ(rising("", EnableLevel::ActiveHigh), 10U);
    EXPECT_EQ(rising("n_enbl_x", EnableLevel::ActiveLow), 4U);  // 310, 410, 510, 610 ns
    EXPECT_EQ(rising("n_enbl_x", EnableLevel::ActiveHigh), 6U);
}

// A run's VCD as cncsim writes it: the carriage's position, a real variable, changes between the pin edges and at
// the same instants ("r<value> <id>", IEEE 1364 §18.2), its identifier "$" and one pin's "#" (VCD identifiers are
// any printable characters). STEP rises at 200, 300, 400 and 500 ns; nENBL is low from 100 to 450 ns: the driver
// acts on three of the four pulses, counted by hand.
TEST(MetricsAnalyze, RealValuesBetweenTheEdgesDoNotHideAnyEdge) {
    const std::string text = R"($timescale 1 ns $end
$scope module cncsim $end
$var wire 1 ! step_x $end
$var wire 1 " dir_x $end
$var wire 1 # n_enbl_x $end
$var real 64 $ carriage_x_mm $end
$upscope $end
$enddefinitions $end
#0
$dumpvars
0!
0"
1#
r0 $
$end
#100
0#
#150
r0.0015 $
#200
1!
#201
r0.00625 $
#202
0!
#300
r1.000000000000001e-05 $
1!
#302
0!
r-0.5 $
#400
1!
#402
0!
#450
1#
r-0.75 $
#500
1!
#502
0!
#600
r1.5 $
)";
    std::istringstream in(text);
    const VcdContents vcd = read_vcd(in, "run.vcd");
    EXPECT_EQ(vcd.signals.at("step_x").rising(), (std::vector<TimePs>{200'000, 300'000, 400'000, 500'000}));
    EXPECT_EQ(vcd.signals.at("n_enbl_x").edges.size(), 2U);
    EXPECT_EQ(vcd.other_variables.at("carriage_x_mm"), "64 bits wide (real)");
    const RunInput run = analyze_input(vcd, "run.vcd", {{"step_x", "dir_x", "n_enbl_x", EnableLevel::ActiveLow}});
    EXPECT_EQ(run.axes.at(0).step.rising(), (std::vector<TimePs>{200'000, 300'000, 400'000}));
    EXPECT_EQ(compute_metrics(run).axes.at(0).rising_edges, 3U);
}

TEST(MetricsAnalyze, EnableOptionSuffix) {
    EXPECT_EQ(parse_enable_option("n_enbl_x:active-low").name, "n_enbl_x");
    EXPECT_EQ(parse_enable_option("n_enbl_x:active-low").active, EnableLevel::ActiveLow);
    EXPECT_EQ(parse_enable_option("en:active-high").active, EnableLevel::ActiveHigh);
    EXPECT_EQ(parse_enable_option("n_enbl_x").active, EnableLevel::ActiveLow);  // the DRV8825's nENBL
    EXPECT_EQ(parse_enable_option("en:active-low").name, "en");
    EXPECT_EQ(parse_enable_option("top:en").name, "top:en");  // a colon of the name stays
}

// Every message names the file and the option; a signal of another width says what it is.
TEST(MetricsAnalyze, MissingSignalsNameTheFileAndWhatTheFileHas) {
    const VcdContents vcd =
        capture({test::step_log(grid(0, 100'000'000, 2)), EdgeLog{"dir_x", false, {}}}, "$var wire 8 ~~ step_z $end\n");
    EXPECT_EQ(error_of(vcd, {"step_y", "dir_x", "", EnableLevel::ActiveHigh}),
              "cap.vcd: --step step_y: no 1-bit signal 'step_y' in the trace; 1-bit signals: dir_x, step_x");
    EXPECT_EQ(error_of(vcd, {"step_z", "dir_x", "", EnableLevel::ActiveHigh}),
              "cap.vcd: --step step_z: no 1-bit signal 'step_z' in the trace: 'step_z' is 8 bits wide (wire); "
              "1-bit signals: dir_x, step_x");
    EXPECT_EQ(error_of(vcd, {"step_x", "dir_q", "", EnableLevel::ActiveHigh}).rfind("cap.vcd: --dir dir_q: ", 0), 0U);
    EXPECT_EQ(error_of(vcd, {"step_x", "dir_x", "en", EnableLevel::ActiveLow}).rfind("cap.vcd: --enable en: ", 0), 0U);
}

}  // namespace
}  // namespace cnc::metrics
