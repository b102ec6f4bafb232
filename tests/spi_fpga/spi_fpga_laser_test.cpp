// The spi-fpga laser (the laser bit of the X rate word) follows the job's M3/M5/S over a whole run, measured by the
// run's report. Job (tests/data/laser/laser_follows_job.nc): the laser is wanted in G1 X10 (M3 S1000) and in the
// last G1 Y0 (M3 S500), not in G1 Y10 (M5) nor G1 X0 (S0), and never in the G0.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "run/run.hpp"
#include "scenario/scenario.hpp"

namespace {

cnc::sim::RunOutcome run_laser_job(const std::vector<std::string>& sets = {}) {
    const std::string path = std::string(CNC_SOURCE_DIR) + "/tests/data/laser/laser_follows_job.toml";
    cnc::sim::Scenario s = cnc::sim::load_scenario(path, sets);
    s.keep_run_input = true;  // the tests read the laser pin's edges
    return cnc::sim::run_scenario(s);
}

// Each wanted cut is 10 mm at F600 = 10 mm/s from rest to rest with the default 1000 mm/s^2 on both axes:
// 10 / 10 + 10 / 1000 = 1.01 s; the two together 2020 ms.
constexpr double kWantedOnMs = 2 * 1010.0;
// The laser switches with the first frame of each cut and the first landing frame after it, a whole number of
// 1 ms servo periods apart; a stretch differs from the cut by the two frames' wake-up latencies (<= 50 us) and
// by one period when the trajectory clock reaches the rest point with a last rounding-sized step.
constexpr double kServoPeriodMs = 1.0;
constexpr double kLatencyMaxMs = 0.05;

}  // namespace

TEST(SpiFpgaLaser, OnForTheCutsTheJobWantsAndNeverInTheRapid) {
    const auto out = run_laser_job();
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& laser = out.report["metrics"]["laser"];
    EXPECT_NEAR(laser["on_ms"].get<double>(), kWantedOnMs, kServoPeriodMs + kLatencyMaxMs);
    EXPECT_EQ(laser["on_in_rapid_ms"].get<double>(), 0.0);
    // Two stretches, one inside each wanted move's window.
    ASSERT_TRUE(out.arch.input.laser.has_value());
    const cnc::EdgeLog& pin = *out.arch.input.laser;
    const std::vector<cnc::TimePs> on = pin.rising();
    const std::vector<cnc::TimePs> off = pin.falling();
    ASSERT_EQ(on.size(), 2U);
    ASSERT_EQ(off.size(), 2U);
    const auto& moves = out.arch.input.moves;
    ASSERT_EQ(moves.size(), 5U);
    for (const auto& [stretch, move] : {std::pair<std::size_t, std::size_t>{0, 0}, {1, 4}}) {
        EXPECT_GE(on[stretch], moves[move].t_begin_ps) << stretch;
        EXPECT_LE(off[stretch], moves[move].t_end_ps) << stretch;
    }
    // The hardware does what the job asks: no warning about the laser differing from it.
    for (const auto& w : out.report["warnings"]) EXPECT_EQ(w.get<std::string>().find("laser"), std::string::npos) << w;
}

TEST(SpiFpgaLaser, ContinuousModeKeepsTheLaserOutOfTheRapidToo) {
    const auto out = run_laser_job({"planner.mode=\"continuous\""});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& laser = out.report["metrics"]["laser"];
    EXPECT_GT(laser["on_ms"].get<double>(), 0.0);
    EXPECT_EQ(laser["on_in_rapid_ms"].get<double>(), 0.0);
    ASSERT_TRUE(out.arch.input.laser.has_value());
    EXPECT_EQ(out.arch.input.laser->rising().size(), 2U);
}
