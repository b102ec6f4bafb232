// load_job's one pass over a G-code job: the whole program's order of errors, and what a streaming architecture
// (fpga-uart) keeps of the program.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

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

}  // namespace
}  // namespace cnc::sim
