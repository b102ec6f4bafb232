// A streamed atmega run (the pins read slice by slice, the motion windows found as PORTB changes, the metrics
// measured and their inputs dropped as they go) against the same run measured whole at the end (compute_metrics on
// every edge and sample, as --plots and --samples ask).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "run/run.hpp"
#include "scenario/scenario.hpp"

namespace {

// The report text of the run, made in a child process (one SystemC elaboration per process); empty if it failed.
std::string report_of(const std::string& scenario, bool keep_logs, const std::filesystem::path& path) {
    const pid_t pid = fork();
    if (pid == 0) {
        cnc::sim::Scenario s = cnc::sim::load_scenario(scenario, {"trace.detail=true"});
        s.keep_run_input = keep_logs;
        const cnc::sim::RunOutcome out = cnc::sim::run_scenario(s);
        std::ofstream f(path);
        cnc::sim::write_report(f, out);
        f.close();
        std::_Exit(out.ok && f ? 0 : 1);
    }
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

// G00 dog-legs, G01s with the laser on and off between them, a Y-only G01 (EN_X stays high), an arc's 45 chords
// (2 degrees each): the detailed reports, every metric, every piece and pulse run, are the same bytes.
TEST(AtmegaStreamed, MetricsEqualTheBatchOnes) {
    const std::string scenario = std::string(CNC_SOURCE_DIR) + "/tests/atmega/data/streamed_mix.toml";
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("AtmegaStreamed.MetricsEqualTheBatchOnes." + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::string streamed = report_of(scenario, false, dir / "streamed.json");
    const std::string batch = report_of(scenario, true, dir / "batch.json");
    std::filesystem::remove_all(dir);
    ASSERT_FALSE(streamed.empty());
    ASSERT_FALSE(batch.empty());
    EXPECT_EQ(streamed, batch);

    // What was compared (streamed_mix.nc): 7 programmed moves, three of them rapids, the arc's 45 chords as
    // pieces, both axes stepping, the laser's on time and dwell measured.
    const nlohmann::json m = nlohmann::json::parse(streamed).at("metrics");
    EXPECT_EQ(m.at("moves").at("rapid"), nlohmann::json({true, false, false, false, true, false, true}));
    EXPECT_EQ(m.at("moves").at("pieces"), nlohmann::json({1, 1, 1, 45, 1, 1, 1}));
    EXPECT_GT(m.at("axes").at(0).at("rising_edges").get<int>(), 0);
    EXPECT_GT(m.at("axes").at(1).at("rising_edges").get<int>(), 0);
    EXPECT_GT(m.at("laser").at("on_ms").get<double>(), 0.0);
    EXPECT_GT(m.at("laser").at("dwell_intervals").get<int>(), 0);
}
