// Dead time between programmed moves and inside them (docs/metrics.md "Job timing"), from `cncsim` reports: inside
// an arc that fpga-uart sends as chords every chord waits for its ACK, and the metrics must count those gaps as its
// own link section (the stop-and-wait breakdown, measured from the busy pin, the CP2102 and the sender) lists them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/command_output.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kScenarios = std::string(CNC_SOURCE_DIR) + "/scenarios/";

// Runs cncsim with `args` and returns what it printed on stdout.
std::string cncsim(const std::string& args) {
    return cnc::test::command_output(std::string(CNCSIM_EXE) + " " + args + " 2>/dev/null");
}

nlohmann::json detailed_report(const std::string& scenario) {
    const fs::path report = fs::temp_directory_path() / ("cncsim-dead_time_test-" + std::to_string(getpid()) + ".json");
    cncsim("run " + scenario + " --detail --progress off --report " + report.string());
    std::ifstream in(report);
    const nlohmann::json j = nlohmann::json::parse(in);
    fs::remove(report);
    return j;
}

}  // namespace

// The circle is one G2 after a G0: its chords are consecutive packets, and the gap after packet k is inside the
// circle when packets k and k + 1 are both chords. The link section measures each gap from the last STEP of one
// packet to the first STEP of the next as the sum of its hand-overs (step tail, ACK, USB, host, packet, FPGA
// set-up); the metrics take the same instants from the STEP pins alone.
TEST(DeadTime, FpgaUartInsideTheCircleIsTheSumOfItsChordGaps) {
    const nlohmann::json r = detailed_report(kScenarios + "fpga-uart/circle_r10.toml");
    const nlohmann::json& job = r.at("metrics").at("job");
    const auto pieces = r.at("metrics").at("moves").at("pieces").get<std::vector<std::size_t>>();
    ASSERT_EQ(pieces.size(), 2U);                   // G0, G2
    const std::size_t first_chord = pieces[0] + 1;  // 1-based packets
    const std::size_t last_chord = pieces[0] + pieces[1];
    double chord_gaps_us = 0.0;
    std::size_t chord_gaps = 0;
    for (const nlohmann::json& g : r.at("fpga-uart").at("dead_time").at("per_gap")) {
        const auto after = g.at("after_packet").get<std::size_t>();
        if (after < first_chord || after + 1 > last_chord) continue;
        chord_gaps_us += g.at("total_us").get<double>();
        ++chord_gaps;
    }
    EXPECT_GT(pieces[1], 100U);  // the host's CAM chords the circle at 2 um tolerance
    EXPECT_EQ(chord_gaps, pieces[1] - 1);
    EXPECT_EQ(job.at("dead_inside_gaps").get<std::size_t>(), pieces[1] - 1);
    EXPECT_NEAR(job.at("dead_inside_total_ms").get<double>() * 1e3, chord_gaps_us, 1.0);
    // The detailed list holds the same gaps, each inside move 2.
    const nlohmann::json& inside = job.at("dead_times_inside");
    ASSERT_EQ(inside.size(), chord_gaps);
    double listed_ms = 0.0;
    for (const nlohmann::json& g : inside) {
        EXPECT_EQ(g.at("move").get<int>(), 2);
        listed_ms += g.at("dead_ms").get<double>();
    }
    EXPECT_NEAR(listed_ms * 1e3, chord_gaps_us, 1.0);
}

// Every gap of the job is between two moves or inside one: on each architecture the total is their sum, and the
// number of gaps is one fewer than the pieces that step.
TEST(DeadTime, TotalIsBetweenPlusInsideOnEveryArchitecture) {
    for (const char* job : {"circle_r10", "square_20mm"}) {
        const nlohmann::json columns = nlohmann::json::parse(cncsim("compare " + kScenarios + "compare/" + job +
                                                                    ".toml --arch ideal,fpga-uart,atmega,spi-fpga "
                                                                    "--format json"));
        ASSERT_EQ(columns.size(), 4U) << job;
        for (const nlohmann::json& c : columns) {
            const auto arch = c.at("architecture").get<std::string>();
            const nlohmann::json& m = c.at("metrics");
            const double between = m.at("metrics/job/dead_total_ms").get<double>();
            const double inside = m.at("metrics/job/dead_inside_total_ms").get<double>();
            const double total = m.at("metrics/job/dead_all_total_ms").get<double>();
            EXPECT_GE(between, 0.0) << job << " " << arch;
            EXPECT_GE(inside, 0.0) << job << " " << arch;
            EXPECT_NEAR(total, between + inside, 1e-9) << job << " " << arch;
            std::printf("%s %s: between %.3f ms, inside %.3f ms, total %.3f ms\n", job, arch.c_str(), between, inside,
                        total);
        }
    }
}
