// load_job's one pass over a G-code job: the whole program's order of errors, and what a streaming architecture
// (fpga-uart) keeps of the program.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "common/bad_input.hpp"
#include "run/job.hpp"
#include "scenario/scenario.hpp"
#include "support/test_path.hpp"

namespace cnc::sim {
namespace {

// An architecture that takes the job as the seed 000 FPGA does (the laser by motion kind), whole or streamed.
class JobReader final : public Architecture {
public:
    explicit JobReader(bool streams) : m_streams(streams) {}
    [[nodiscard]] std::string name() const override { return "job-reader"; }
    [[nodiscard]] JobUse job_use() const override { return {true, false, LaserSwitching::ByMotionKind, m_streams}; }
    [[nodiscard]] std::shared_ptr<const ArchSettings> read_settings(KeyReader&, const Scenario&,
                                                                    const std::filesystem::path&) const override {
        return nullptr;
    }
    [[nodiscard]] std::string plot_colour() const override { return "#000000"; }

private:
    bool m_streams;
};

const Architecture& architecture(bool keep_moves) {
    static const JobReader whole(false), streamed(true);
    return keep_moves ? static_cast<const Architecture&>(whole) : streamed;
}

// A scenario on the default machine with 100 mm of X travel, and its job, in the test's own folder.
Scenario scenario_with_job(const std::string& name, const std::string& gcode) {
    const std::string job = test::test_path(name + ".nc");
    std::ofstream(job) << gcode;
    const std::string path = test::test_path(name + ".toml");
    std::ofstream(path) << "[scenario]\njob = \"" << job << "\"\n[machine.x]\ntravel_mm = 100\n";
    return load_scenario(path, {});
}

std::string load_error(const Scenario& s, bool keep_moves) {
    try {
        (void)load_job(s, architecture(keep_moves));
    } catch (const BadInput& e) {
        return e.what();
    }
    return "";
}

TEST(LoadJob, TheFilesProblemsThenTheSoftLimitsThenTheMachineLimitsWhateverTheirLines) {
    // Line 1 takes 10 mm at 1e-6 mm/min, 6e8 s (past the longest job, 1e6 s) inside the travel; line 2 leaves the
    // 100 mm travel; line 3 is an unsupported word.
    const std::string head = "G1 X10 F0.000001\nG1 X200 F100\n";
    for (const bool keep : {true, false}) {
        const Scenario all = scenario_with_job("problems_" + std::to_string(keep), head + "G33 X1\n");
        EXPECT_NE(load_error(all, keep).find(":3: unsupported word 'G33'"), std::string::npos) << load_error(all, keep);
        const Scenario limits = scenario_with_job("limits_" + std::to_string(keep), head);
        const std::string err = load_error(limits, keep);
        EXPECT_NE(err.find(":2: X 200 mm is past machine.x.travel_mm = 100"), std::string::npos) << err;
        const Scenario time = scenario_with_job("time_" + std::to_string(keep), "G1 X10 F0.000001\n");
        EXPECT_NE(load_error(time, keep).find(":1: the job reaches 6e+08 s"), std::string::npos)
            << load_error(time, keep);
    }
}

TEST(LoadJob, AStreamingArchitectureKeepsTheSummaryAndTheMoveWarnings) {
    // Two XY moves, the second cutting under M5 (line 3): the seed 000 FPGA burns it anyway.
    const Scenario s = scenario_with_job("summary", "G0 X1\nM5\nG1 X2 F600\nM30\n");
    const Job streamed = load_job(s, architecture(false));
    ASSERT_TRUE(streamed.program.has_value());
    EXPECT_TRUE(streamed.program->moves.empty());
    EXPECT_EQ(streamed.program->move_count, 2u);
    EXPECT_EQ(streamed.program->lines, 4);
    ASSERT_EQ(streamed.move_warnings.size(), 1u);
    EXPECT_EQ(streamed.move_warnings[0].kind, "laser_on_unasked");
    EXPECT_NE(streamed.move_warnings[0].where.find(":3"), std::string::npos) << streamed.move_warnings[0].where;
    const Job whole = load_job(s, architecture(true));
    EXPECT_EQ(whole.program->moves.size(), 2u);
    EXPECT_EQ(whole.move_warnings.size(), 1u);
}

// The default machine with X held to 150 mm/s and Y to 100 mm/s.
Scenario limited_machine(const std::string& name, const std::string& gcode) {
    const std::string job = test::test_path(name + ".nc");
    std::ofstream(job) << gcode;
    const std::string path = test::test_path(name + ".toml");
    std::ofstream(path) << "[scenario]\njob = \"" << job
                        << "\"\n[machine.x]\nmax_velocity_mm_per_s = 150\n[machine.y]\nmax_velocity_mm_per_s = 100\n";
    return load_scenario(path, {});
}

std::vector<Warning> held_warnings(const Job& job) {
    std::vector<Warning> held;
    for (const Warning& w : job.move_warnings) {
        if (w.kind == "feed_held") held.push_back(w);
    }
    return held;
}

TEST(LoadJob, AFeedAboveTheAxisLimitsIsAWarningPerRunOfLinesWithBothFeeds) {
    // Lines 2-3 along X at F20000 (333 mm/s): held to 150 mm/s = F9000; line 4 the same feed along Y, held by Y to
    // 100 mm/s = F6000; line 5 at F5000 within both; line 6 (0.6, 0.8) at F20000: X may go 150 / 0.6 = 250 mm/s, Y
    // 100 / 0.8 = 125 mm/s, so F7500 by Y.
    const Scenario s =
        limited_machine("held", "G0 X0 Y0\nG1 X10 F20000\nG1 X20\nG1 Y10\nG1 Y20 F5000\nG1 X26 Y28 F20000\nM30\n");
    const std::vector<Warning> held = held_warnings(load_job(s, architecture(true)));
    ASSERT_EQ(held.size(), 3u);
    EXPECT_EQ(held[0].where, s.job_path + ":2-3");
    EXPECT_NE(held[0].text.find("feed 20000.0 mm/min held to 9000.0 mm/min by machine.x.max_velocity_mm_per_s = 150"),
              std::string::npos)
        << held[0].text;
    EXPECT_EQ(held[1].where, s.job_path + ":4");
    EXPECT_NE(held[1].text.find("held to 6000.0 mm/min by machine.y.max_velocity_mm_per_s = 100"), std::string::npos)
        << held[1].text;
    EXPECT_EQ(held[2].where, s.job_path + ":6");
    EXPECT_NE(held[2].text.find("held to 7500.0 mm/min by machine.y"), std::string::npos) << held[2].text;
}

TEST(LoadJob, AnArcIsHeldWhereItsTangentRunsMostAlongTheLimitingAxis) {
    // Line 2: a full circle of radius 10 at F20000 runs along Y at its right and left: F6000 there. Line 3: from 30
    // to 60 degrees about (0, 0), crossing no axis: the tangent (-sin 30, cos 30) at the start asks the most of Y,
    // 100 / cos 30 = 115.47 mm/s = F6928.2. Line 4: a rapid is at the machine's rapid speed, not the job's F.
    const double deg30_rad = std::atan(1.0) * 4.0 / 6.0;
    const double c30 = 10.0 * std::cos(deg30_rad), s30 = 10.0 * std::sin(deg30_rad);
    std::ostringstream g;
    g << std::setprecision(17) << "G0 X10 Y0\nG2 I-10 J0 F20000\nG0 X" << c30 << " Y" << s30 << "\nG3 X" << s30 << " Y"
      << c30 << " I" << -c30 << " J" << -s30 << "\nG0 X0 Y0\n";
    const Scenario s = limited_machine("held_arc", g.str());
    const std::vector<Warning> held = held_warnings(load_job(s, architecture(true)));
    ASSERT_EQ(held.size(), 2u);
    EXPECT_EQ(held[0].where, s.job_path + ":2");
    EXPECT_NE(held[0].text.find("held to 6000.0 mm/min by machine.y"), std::string::npos) << held[0].text;
    EXPECT_EQ(held[1].where, s.job_path + ":4");
    EXPECT_NE(held[1].text.find("held to 6928.2 mm/min by machine.y"), std::string::npos) << held[1].text;
}

}  // namespace
}  // namespace cnc::sim
