#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include "metrics/metrics.hpp"
#include "metrics/report/report.hpp"
#include "metrics_test_util.hpp"

namespace cnc::metrics {
namespace {

using test::grid;

// Each kind of programmed move and where it ends, from the piece's programmed path: a chord's parent arc gives its
// centre and direction, a G0 is a rapid whatever its path.
TEST(ProgrammedEnd, KindEndAndCentreFromTheProgrammedPath) {
    MoveSpec arc;
    arc.path = geom::Segment::arc({10, 0}, {0, 10}, {0, 0}, true);
    arc.z_end_mm = -1.5;
    ProgrammedEnd e = programmed_end(arc);
    EXPECT_STREQ(to_string(e.kind), "arc_ccw");
    EXPECT_EQ(e.x_mm, arc.path.end.x_mm);
    EXPECT_EQ(e.y_mm, arc.path.end.y_mm);
    EXPECT_EQ(e.z_mm, -1.5);
    EXPECT_EQ(e.center_x_mm, 0.0);
    EXPECT_EQ(e.center_y_mm, 0.0);
    arc.path = geom::Segment::arc({10, 0}, {0, -10}, {0, 0}, false);
    EXPECT_STREQ(to_string(programmed_end(arc).kind), "arc_cw");
    MoveSpec line;
    line.path = geom::Segment::line({1, 2}, {3.25, -4.5});
    e = programmed_end(line);
    EXPECT_STREQ(to_string(e.kind), "line");
    EXPECT_EQ(e.x_mm, 3.25);
    EXPECT_EQ(e.y_mm, -4.5);
    EXPECT_FALSE(e.center_x_mm.has_value());
    line.rapid = true;
    EXPECT_STREQ(to_string(programmed_end(line).kind), "rapid");
}

RunMetrics seed_example_metrics() {
    // The seed 000 worked example plus a laser that is on only while cutting.
    const TimePs t0 = 3 * kPsPerMs;
    RunInput in;
    in.axes.push_back(test::axis(grid(t0, 20'973 * test::kFpgaClockPs, 1600), "x"));
    in.axes.push_back(test::axis(grid(t0, 41'946 * test::kFpgaClockPs, 800), "y"));
    in.axes[0].steps_per_mm = 160.0;
    in.axes[1].steps_per_mm = 160.0;
    MoveSpec move = test::line_move(0, {0, 0}, {10, 5}, 1000.0, 0, 700 * kPsPerMs);
    move.steps = {1600, 800};
    move.rate_steps_per_s = {1600.0 / 0.67082039325, 800.0 / 0.67082039325};
    in.moves.push_back(move);
    in.laser = EdgeLog{"laser", false, {{t0, true}, {t0 + 671 * kPsPerMs, false}}};
    in.t_job_end_ps = 700 * kPsPerMs;
    return compute_metrics(in);
}

TEST(MetricsReport, JsonKeysCarryUnitsAndAbsentFiguresAreNull) {
    const nlohmann::json j = to_json(seed_example_metrics());
    EXPECT_EQ(j["limits"]["step_high_min_ns"], 1900.0);
    EXPECT_EQ(j["limits"]["step_rate_max_hz"], 250000.0);
    EXPECT_TRUE(j["run_split_tolerance"].is_null());  // runs come from the moves
    ASSERT_EQ(j["axes"].size(), 2U);
    const nlohmann::json& x = j["axes"][0];
    EXPECT_EQ(x["axis"], "x");
    EXPECT_EQ(x["step_signal"], "step_x");
    EXPECT_EQ(x["rising_edges"], 1600);
    EXPECT_EQ(x["net_steps"], 1600);  // DIR stayed high, and high is positive
    EXPECT_DOUBLE_EQ(x["travel_mm"].get<double>(), 10.0);
    EXPECT_EQ(x["driver_timing"]["step_high"]["violations"], 0);
    EXPECT_EQ(x["driver_timing"]["step_high"]["min_ns"], 2000.0);
    EXPECT_TRUE(x["driver_timing"]["dir_setup"]["min_ns"].is_null());  // DIR never changed
    EXPECT_EQ(x["runs"].size(), 1U);
    EXPECT_EQ(x["runs"][0]["move"], 0);
    EXPECT_EQ(x["runs"][0]["jitter_std_ns"], 0.0);
    EXPECT_NEAR(x["runs"][0]["speed_mm_per_min"].get<double>(), 1600.0 / 0.671136 / 160.0 * 60.0, 1e-9);
    // The moves as columns, per-axis ones by axis name.
    ASSERT_EQ(j["moves"]["index"], (std::vector<int>{0}));
    EXPECT_NEAR(j["moves"]["feed_error_pct"][0].get<double>(), -0.047, 0.001);
    EXPECT_EQ(j["moves"]["steps_commanded"]["x"], (std::vector<int>{1600}));
    EXPECT_EQ(j["moves"]["steps_commanded"]["y"], (std::vector<int>{800}));
    EXPECT_TRUE(j["moves"]["contour_max_um"][0].is_null());  // no tool samples
    EXPECT_EQ(j["moves"]["sync_max_ns"]["x"].size(), 1U);
    EXPECT_TRUE(j["job"]["dead_times"].empty());
    EXPECT_TRUE(j["worst_moves"]["contour_max_um"].empty());
    ASSERT_EQ(j["worst_moves"]["feed_error_pct"].size(), 1U);
    EXPECT_EQ(j["worst_moves"]["feed_error_pct"][0]["move"], 0);
    EXPECT_EQ(j["worst_moves"]["feed_error_pct"][0]["feed_error_pct"], j["moves"]["feed_error_pct"][0]);
    EXPECT_TRUE(j["path"]["contour_max_um"].is_null());
    EXPECT_EQ(j["feed"]["cutting_moves_measured"], 1);
    EXPECT_DOUBLE_EQ(j["job"]["job_time_s"].get<double>(), 0.7);
    EXPECT_EQ(j["job"]["dead_gaps"], 0);
    EXPECT_NEAR(j["laser"]["on_ms"].get<double>(), 671.0, 1e-9);
    EXPECT_EQ(j["laser"]["on_in_rapid_ms"], 0.0);
    EXPECT_TRUE(j["laser"]["dwell_ms"].is_null());  // no tool samples
    EXPECT_EQ(j["pulse"]["driver_violations"], 0);
    EXPECT_NEAR(j["pulse"]["sync_max_us"].get<double>(), j["pulse"]["sync_max_ns"].get<double>() / 1000.0, 1e-12);
}

// Without detail: no pulse runs, no dead-time gaps, and only the default per-move columns, rounded.
TEST(MetricsReport, DefaultReportLeavesOutWhatGrowsWithStepsAndGaps) {
    const nlohmann::json j = to_json(seed_example_metrics(), false);
    EXPECT_FALSE(j["axes"][0].contains("runs"));
    EXPECT_EQ(j["axes"][0]["runs_count"], 1);
    EXPECT_FALSE(j["job"].contains("dead_times"));
    const nlohmann::json& moves = j["moves"];
    for (const char* key :
         {"index", "line", "rapid", "feed_mm_per_min", "t_first_edge_ps", "motion_time_s", "feed_error_pct",
          "contour_max_um", "following_max_um", "steps_commanded", "steps_emitted"}) {
        EXPECT_TRUE(moves.contains(key)) << key;
    }
    for (const char* key : {"t_last_edge_ps", "achieved_feed_mm_per_min", "tool_samples", "following_rms_um",
                            "endpoint_vs_command_um", "endpoint_vs_program_um", "sync_max_ns"}) {
        EXPECT_FALSE(moves.contains(key)) << key;
    }
    // 1600 steps at 20,973 clocks of 20 ns: 0.671136 s for sqrt(125) mm at F1000; the error to 1e-4 %.
    const double error_pct = (std::sqrt(125.0) / 0.671136 * 60.0 / 1000.0 - 1.0) * 100.0;
    EXPECT_EQ(moves["feed_error_pct"][0].get<double>(), std::round(error_pct * 1e4) / 1e4);
    EXPECT_EQ(moves["motion_time_s"][0].get<double>(), 0.671136);
    EXPECT_EQ(moves["t_first_edge_ps"][0], 3 * kPsPerMs);
}

TEST(MetricsReport, SummaryTableHasOneSectionPerFamilyWithUnitsInHeads) {
    const std::string s = summary_table(seed_example_metrics());
    for (const char* title :
         {"Edges\n", "Pulse timing (one run per move and axis)\n", "Driver timing (DRV8825), total violations 0\n",
          "Feed (cutting moves)\n", "Job timing\n", "Laser\n"}) {
        EXPECT_NE(s.find(title), std::string::npos) << title;
    }
    EXPECT_EQ(s.find("Path accuracy"), std::string::npos);  // no tool samples
    EXPECT_NE(s.find("TIE max [ns]"), std::string::npos);
    EXPECT_NE(s.find("feed error max abs [%]"), std::string::npos);
    // Driver rows: axis, rule, limit, min seen, checked, violations.
    EXPECT_NE(s.find("x     step_high      1900.0         2000.0     1600           0\n"), std::string::npos) << s;
    // Feed: 1 cutting move measured, none held below F (no planner).
    EXPECT_NE(s.find("            1        0              -0.0470                   0.0470                  0.0470\n"),
              std::string::npos)
        << s;
    // One move (index 0, line 1) without tool samples: no contour or following figure; its feed error is first.
    EXPECT_NE(s.find("Worst moves (move index, G-code line)\n"), std::string::npos);
    EXPECT_NE(
        s.find("   1                 -     -     -                   -     -     -         -0.0470     0     1\n"),
        std::string::npos)
        << s;
}

TEST(MetricsReport, OutOfOrderInputIsAProgrammingError) {
    RunInput in;
    in.axes.push_back(test::axis({}));
    in.axes[0].step.edges = {{10, true}, {5, false}};
    EXPECT_THROW((void)compute_metrics(in), std::invalid_argument);
    RunInput moves;
    moves.moves.push_back(test::line_move(0, {}, {}, 600.0, 10, 20));
    moves.moves.push_back(test::line_move(1, {}, {}, 600.0, 5, 20));
    EXPECT_THROW((void)compute_metrics(moves), std::invalid_argument);
}

}  // namespace
}  // namespace cnc::metrics
