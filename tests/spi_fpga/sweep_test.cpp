// Following error grows with the servo thread's latency bound and with its period: the studies of
// sweeps/spi_fpga_servo_loop.toml, run once by `cncsim sweep` (each point its own cncsim process), read from its
// results.json.
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

// Each test is a process of its own (ctest may run both at once): each runs the sweep into its own folder.
std::vector<Point> sweep(const std::string& study) {
    const nlohmann::json results = [&] {
        const std::string out = cnc::test::test_path("servo_loop_" + study);
        const std::string cmd = std::string(CNCSIM) + " sweep " + CNC_SOURCE_DIR +
                                "/sweeps/spi_fpga_servo_loop.toml --out " + out + " 2> /dev/null";
        EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
        std::ifstream in(out + "/results.json");
        return nlohmann::json::parse(in);
    }();
    std::vector<Point> out;
    for (const nlohmann::json& p : results["points"]) {
        if (p["study"] != study) continue;
        EXPECT_EQ(p["status"], "ok") << p["point"];
        const nlohmann::json& m = p["metrics"];
        out.push_back(
            {m["/metrics/path/following_max_um"].get<double>(), m["/metrics/path/following_rms_um"].get<double>()});
        std::cout << study << " " << p["values"].dump() << ": following error max " << out.back().following_max_um
                  << " um, RMS " << out.back().following_rms_um << " um\n";
    }
    return out;
}

}  // namespace

TEST(SpiFpgaSweep, FollowingErrorGrowsWithTheLatencyBound) {
    const auto pts = sweep("latency");
    ASSERT_EQ(pts.size(), 5u);
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
    const auto pts = sweep("servo_period");
    ASSERT_EQ(pts.size(), 4u);
    for (std::size_t i = 1; i < pts.size(); ++i) {
        EXPECT_GT(pts[i].following_max_um, pts[i - 1].following_max_um) << i;
        EXPECT_GT(pts[i].following_rms_um, pts[i - 1].following_rms_um) << i;
    }
    // the law follows one period behind: at the 141 mm/s rapids that is 141 um per ms of period
    EXPECT_GT(pts[3].following_max_um, 1.7 * pts[2].following_max_um);
    EXPECT_GT(pts[2].following_max_um, 1.7 * pts[1].following_max_um);
}
