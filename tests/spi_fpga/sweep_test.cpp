// Following error grows with the servo thread's latency bound and with its period. Each sweep
// point is its own cncsim process (one SystemC elaboration per process); the test reads their JSON reports.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/test_path.hpp"

namespace {

struct Point {
    double following_max_um;
    double following_rms_um;
};

Point run(const std::string& scenario) {
    const std::string report = cnc::test::test_path(scenario + ".json");
    const std::string cmd = std::string(CNCSIM) + " run " + CNC_SOURCE_DIR + "/scenarios/spi-fpga/sweeps/" + scenario +
                            ".toml --report " + report + " > /dev/null";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream in(report);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_TRUE(j["ok"].get<bool>()) << scenario;
    const auto& p = j["metrics"]["path"];
    return {p["following_max_um"].get<double>(), p["following_rms_um"].get<double>()};
}

std::vector<Point> sweep(const std::vector<std::string>& scenarios) {
    std::vector<Point> out;
    for (const std::string& s : scenarios) {
        out.push_back(run(s));
        std::cout << s << ": following error max " << out.back().following_max_um << " um, RMS "
                  << out.back().following_rms_um << " um\n";
    }
    return out;
}

}  // namespace

TEST(SpiFpgaSweep, FollowingErrorGrowsWithTheLatencyBound) {
    const auto pts = sweep({"latency_000us", "latency_020us", "latency_050us", "latency_100us", "latency_200us"});
    // The max at every step; the RMS over the whole sweep only: a 20 us bound adds about 141 mm/s x its mean
    // latency (uniform: 10 us) = 1.4 um to the RMS, as much as the draws of one seed move it either way.
    for (std::size_t i = 1; i < pts.size(); ++i) {
        EXPECT_GT(pts[i].following_max_um, pts[i - 1].following_max_um) << i;
    }
    EXPECT_GT(pts.back().following_rms_um, pts.front().following_rms_um);
    // 200 us of latency at the square's 141 mm/s rapids: about 141 mm/s x 200 us = 28 um more than none
    EXPECT_GT(pts.back().following_max_um - pts.front().following_max_um, 20.0);
}

TEST(SpiFpgaSweep, FollowingErrorGrowsWithTheServoPeriod) {
    const auto pts = sweep({"period_0250us", "period_0500us", "period_1000us", "period_2000us"});
    for (std::size_t i = 1; i < pts.size(); ++i) {
        EXPECT_GT(pts[i].following_max_um, pts[i - 1].following_max_um) << i;
        EXPECT_GT(pts[i].following_rms_um, pts[i - 1].following_rms_um) << i;
    }
    // the law follows one period behind: at the 141 mm/s rapids that is 141 um per ms of period
    EXPECT_GT(pts[3].following_max_um, 1.7 * pts[2].following_max_um);
    EXPECT_GT(pts[2].following_max_um, 1.7 * pts[1].following_max_um);
}
