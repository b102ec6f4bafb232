// cncsim compare: the three architectures on the same square and machine, each in its own process.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "compare/compare.hpp"
#include "support/command_output.hpp"

namespace {

nlohmann::json run_compare_json(const std::string& args) {
    return nlohmann::json::parse(
        cnc::test::command_output(std::string(CNCSIM_EXE) + " compare " + args + " --format json"));
}

double metric(const nlohmann::json& column, const char* key) {
    return column.at("metrics").at(key).get<double>();
}

}  // namespace

// What each architecture costs on one job: dead time (stop-and-wait vs one byte per confirm vs a servo loop),
// feed accuracy (packet feed vs 8-bit OCR vs period word) and following error (the servo loop's lag).
TEST(CompareSquare, EachArchitectureShowsItsOwnCost) {
    // Ideal mechanics: every controller that counts its steps ends the job on the point, to the step.
    const auto cols = run_compare_json(std::string(CNC_SOURCE_DIR) +
                                       "/scenarios/fpga-uart/square_20mm.toml --set mechanics.model=ideal");
    ASSERT_EQ(cols.size(), 3U);
    const auto& fpga = cols.at(0);
    const auto& avr = cols.at(1);
    const auto& spi = cols.at(2);
    EXPECT_EQ(fpga.at("architecture"), "fpga-uart");
    EXPECT_EQ(avr.at("architecture"), "atmega");
    EXPECT_EQ(spi.at("architecture"), "spi-fpga");
    for (const auto& c : cols) {
        EXPECT_EQ(c.at("status"), "ok");
        EXPECT_LE(metric(c, "metrics/pulse/tie_max_ns"), 20.0);  // every controller's edges sit on its clock
        EXPECT_EQ(metric(c, "metrics/path/job_end_um"), 0.0);
        EXPECT_EQ(metric(c, "metrics/pulse/driver_violations"), 0.0);
        // The square's rapids run with the laser off on every architecture: by motion code on fpga-uart and
        // atmega, by the frame's laser bit on spi-fpga.
        EXPECT_EQ(metric(c, "metrics/laser/on_in_rapid_ms"), 0.0);
    }
    EXPECT_GT(metric(avr, "metrics/job/dead_mean_ms"), 3 * metric(fpga, "metrics/job/dead_mean_ms"));
    EXPECT_LT(metric(spi, "metrics/job/dead_total_ms"), metric(fpga, "metrics/job/dead_total_ms"));
    EXPECT_GT(metric(avr, "metrics/feed/feed_error_max_abs_pct"), 20.0);  // F800 -> OCR 2.66 truncated to 2
    EXPECT_LT(metric(fpga, "metrics/feed/feed_error_max_abs_pct"), 0.01);
    // The servo loop lags one 1 ms period behind the plan: at the 20 mm/s rapids (1200 mm/min) that is 20 um.
    EXPECT_GT(metric(spi, "metrics/path/following_max_um"), 20.0);
}

// One machine for every architecture: an X velocity limit of 1 mm/s holds each
// architecture's two 20 mm X sides of the square to at least 20 s each, where F800 would take 1.5 s.
TEST(CompareSquare, TheMachineVelocityLimitHoldsEveryArchitecture) {
    const auto cols = run_compare_json(std::string(CNC_SOURCE_DIR) +
                                       "/scenarios/fpga-uart/square_20mm.toml --set machine.x.max_velocity_mm_per_s=1"
                                       " --set host.ack_timeout_s=60");  // the first rapid now takes 10 s
    ASSERT_EQ(cols.size(), 3U);
    for (const auto& c : cols) {
        EXPECT_EQ(c.at("status"), "ok") << c.at("architecture");
        // atmega's 8-bit compare value makes 1 mm/s into 1.017 mm/s (OCR 47): 2 x 20 mm / 1.017 mm/s = 39.3 s.
        EXPECT_GT(metric(c, "metrics/job/job_time_s"), 39.0) << c.at("architecture");
    }
}

// The best of a row is the smallest magnitude as printed, marked only when two or more runs have the figure and
// they differ, and only on a row whose figures are the same quantity in every column: the rate error is measured
// against each architecture's own commanded rates (a planner's on spi-fpga), so -0.01 % is not marked over +0.02 %.
TEST(CompareTable, BestValueOfEachRowIsMarked) {
    const auto col = [](const char* arch, double job_s, double rate_pct, double tie_ns) {
        const nlohmann::json pulse = {{"rate_error_worst_pct", rate_pct}, {"tie_max_ns", tie_ns}};
        return cnc::sim::CompareColumn{arch, 0, {{"metrics", {{"job", {{"job_time_s", job_s}}}, {"pulse", pulse}}}}};
    };
    const std::vector<cnc::sim::CompareColumn> cols = {col("fpga-uart", 8.0, 0.02, 0.0), col("atmega", 7.0, -0.01, 0.0),
                                                       col("spi-fpga", 7.0, 24.0, 0.0)};
    const std::string md =
        cnc::sim::compare_table(cnc::sim::Comparison{cols, std::nullopt}, cnc::sim::TableFormat::Markdown);
    EXPECT_NE(md.find("| job time [s]                      |    8.0000 | **7.0000** | **7.0000** |"), std::string::npos)
        << md;
    EXPECT_NE(md.find("| rate error worst [%]              |   +0.0200 |    -0.0100 |   +24.0000 |"), std::string::npos)
        << md;
    EXPECT_NE(md.find("No best is marked on rate error worst [%], sync error max [us], feed error max [%], following "
                      "error max [um]: "),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| TIE max [ns]                      |     0.000 |      0.000 |      0.000 |"), std::string::npos)
        << md;
    const std::string csv =
        cnc::sim::compare_table(cnc::sim::Comparison{cols, std::nullopt}, cnc::sim::TableFormat::Csv);
    EXPECT_NE(csv.find("\"job time [s]\",\"8.0000\",\"7.0000\",\"7.0000\",\"atmega spi-fpga\""), std::string::npos)
        << csv;
    const nlohmann::json j = cnc::sim::compare_json(cnc::sim::Comparison{cols, std::nullopt});
    EXPECT_EQ(j.at(1).at("best"), nlohmann::json({"metrics/job/job_time_s"}));
}

// One rapid speed for every architecture (machine.rapid_feed_mm_per_min): halving it from 1200 to 600 mm/min slows
// each architecture's two G0 moves of the square, (0,0)->(10,10) and back (1600 steps per axis at 160 steps/mm),
// by what its own arithmetic gives, and nothing else changes:
// - fpga-uart: the G0 feed is reduced to the dominant axis (host.correct_rapid_feed) and rounded: 1200 x 10/14.142
//   = 848.5 -> 849 and 424.3 -> 424 mm/min; 10 mm at those feeds takes 0.70671 and 1.41509 s: +1.41677 s for two
//   (the FPGA's whole-clock periods and the 1 ms USB frames that carry each ACK move that by under 5 ms).
// - atmega: each axis of a G00 runs at the rapid speed with one OCR = f/(2 N v/s) - 1 truncated (seed 003 eq.
//   4.77, f = 16 MHz, N = 1024, s = 1/160 mm): 20 mm/s -> 1.44 -> 1, 10 mm/s -> 3.88 -> 3; 1600 steps of 2 N (OCR + 1)
//   cycles take 0.4096 and 0.8192 s: +0.8192 s for two, exact on the AVR's clock (5 ms for the link's bytes).
// - spi-fpga: the planner runs the 14.142 mm at 20 or 10 mm/s: L/v is 0.70711 and 1.41421 s, +1.41421 s for two;
//   each of the four speed changes at the diagonal's 1414 mm/s^2 (1000 mm/s^2 per axis) adds at most v/(2a) =
//   7.1 ms to either run, so the difference is within 30 ms of that.
TEST(CompareSquare, TheMachineRapidSpeedHoldsEveryArchitecture) {
    const std::string square = std::string(CNC_SOURCE_DIR) + "/scenarios/fpga-uart/square_20mm.toml";
    const auto base = run_compare_json(square);
    const auto slow = run_compare_json(square + " --set machine.rapid_feed_mm_per_min=600");
    ASSERT_EQ(base.size(), 3U);
    ASSERT_EQ(slow.size(), 3U);
    const struct {
        double extra_s;
        double tolerance_s;
    } expected[] = {{2.0 * (10.0 / (424.0 / 60.0) - 10.0 / (849.0 / 60.0)), 0.005},
                    {2.0 * 1600.0 * 2048.0 * ((3 + 1) - (1 + 1)) / 16e6, 0.005},
                    {2.0 * (std::sqrt(200.0) / 10.0 - std::sqrt(200.0) / 20.0), 0.030}};
    for (std::size_t i = 0; i < 3; ++i) {
        const auto& arch = slow[i].at("architecture");
        EXPECT_EQ(base[i].at("machine").at("rapid_feed_mm_per_min"), 1200.0) << arch;
        EXPECT_EQ(slow[i].at("machine").at("rapid_feed_mm_per_min"), 600.0) << arch;
        const double extra_s = metric(slow[i], "metrics/job/job_time_s") - metric(base[i], "metrics/job/job_time_s");
        EXPECT_NEAR(extra_s, expected[i].extra_s, expected[i].tolerance_s) << arch;
    }
}

TEST(CompareTable, MarkdownHasAColumnPerArchitectureAndDashesForMissingValues) {
    cnc::sim::CompareColumn a{"fpga-uart", 0, {{"metrics", {{"job", {{"job_time_s", 1.5}}}}}}};
    cnc::sim::CompareColumn b{"atmega", 2, nullptr};
    const std::string md =
        cnc::sim::compare_table(cnc::sim::Comparison{{a, b}, std::nullopt}, cnc::sim::TableFormat::Markdown);
    EXPECT_NE(md.find("| metric                            | fpga-uart |    atmega |"), std::string::npos) << md;
    EXPECT_NE(md.find("| status                            |        ok | bad input |"), std::string::npos) << md;
    EXPECT_NE(md.find("| job time [s]                      |    1.5000 |         - |"), std::string::npos) << md;
    EXPECT_NE(cnc::sim::compare_table(cnc::sim::Comparison{{a}, std::nullopt}, cnc::sim::TableFormat::Csv)
                  .find("\"job time [s]\",\"1.5000\""),
              std::string::npos);
}

// The machine rows are what the run was given: shown for a failed run too, whose results are not.
TEST(CompareTable, StatesTheMachineOfEveryRunEvenAFailedOne) {
    const nlohmann::json machine = {{"rapid_feed_mm_per_min", 1200.0},
                                    {"x", {{"steps_per_mm", 160.0}, {"max_velocity_mm_per_s", 100.0}}}};
    const nlohmann::json report = {{"scenario", {{"machine", machine}}}, {"metrics", {{"job", {{"job_time_s", 1.5}}}}}};
    cnc::sim::CompareColumn failed{"fpga-uart", 1, report};
    const std::string md =
        cnc::sim::compare_table(cnc::sim::Comparison{{failed}, std::nullopt}, cnc::sim::TableFormat::Markdown);
    EXPECT_NE(md.find("| machine: X steps/mm               |  160.0000 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| machine: X velocity max [mm/s]    |     100.0 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| machine: rapid speed [mm/min]     |    1200.0 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| job time [s]                      |         - |"), std::string::npos) << md;
    EXPECT_EQ(cnc::sim::compare_json(cnc::sim::Comparison{{failed}, std::nullopt}).at(0).at("machine"), machine);
}
