// The sweep file's reader: ranges, the grid and zip expansion, and every refusal naming the file's line and key.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "common/bad_input.hpp"
#include "support/test_path.hpp"
#include "sweep/sweep_file.hpp"
#include "sweep/sweep_points.hpp"

namespace {

using cnc::sim::read_sweep_file;

std::string write(const std::string& name, const std::string& text) {
    const std::string path = cnc::test::test_path(name);
    std::ofstream(path) << text;
    return path;
}

// The message of reading `text` as a sweep file, "" when it reads.
std::string refusal(const std::string& name, const std::string& text) {
    try {
        (void)read_sweep_file(write(name, text));
    } catch (const cnc::BadInput& e) {
        return e.what();
    }
    return "";
}

const std::string kHead = "scenario = \"s.toml\"\nmetrics = [\"/metrics/job/job_time_s\"]\n";

}  // namespace

TEST(SweepRange, LinearStepsReachTheEndDespiteRounding) {
    // 0.1 + 0.1 + 0.1 is 0.30000000000000004 in doubles: the range still ends at 0.3, shown as such.
    EXPECT_EQ(cnc::sim::linear_range(0.0, 0.3, 0.1), (std::vector<double>{0.0, 0.1, 0.2, 0.3}));
    EXPECT_EQ(cnc::sim::linear_range(10.0, 4.0, -3.0), (std::vector<double>{10.0, 7.0, 4.0}));
    EXPECT_EQ(cnc::sim::linear_range(1.0, 2.5, 1.0), (std::vector<double>{1.0, 2.0}));
    EXPECT_THROW((void)cnc::sim::linear_range(1.0, 2.0, 0.0), std::invalid_argument);
    EXPECT_THROW((void)cnc::sim::linear_range(1.0, 2.0, -1.0), std::invalid_argument);
}

TEST(SweepRange, LogRangeInEqualRatios) {
    EXPECT_EQ(cnc::sim::log_range(250.0, 2000.0, 4), (std::vector<double>{250.0, 500.0, 1000.0, 2000.0}));
    EXPECT_EQ(cnc::sim::log_range(1e-6, 1e-3, 4), (std::vector<double>{1e-6, 1e-5, 1e-4, 1e-3}));
    EXPECT_THROW((void)cnc::sim::log_range(0.0, 1.0, 3), std::invalid_argument);
    EXPECT_THROW((void)cnc::sim::log_range(1.0, 10.0, 1), std::invalid_argument);
    EXPECT_EQ(cnc::sim::number_text(1e-5), "1e-05");
    EXPECT_EQ(cnc::sim::number_text(250.0), "250");
}

TEST(SweepFile, GridExpandsEveryCombinationWithTheLastAxisFastestThenTheSeeds) {
    const cnc::sim::SweepSpec spec = read_sweep_file(write(
        "grid.toml", kHead +
                         "architectures = [\"a\", \"b\"]\nseeds = 2\nset = [\"k.z = 1\"]\n"
                         "vary = [{ key = \"k.x\", values = [1, 2.5] }, { key = \"k.y\", values = [\"u\", true] }]\n"));
    EXPECT_EQ(spec.input, cnc::test::test_path("s.toml"));  // relative to the sweep file
    const std::vector<cnc::sim::SweepPoint> points = cnc::sim::expand_points(spec, "unused");
    ASSERT_EQ(points.size(), 2u * 2u * 2u * 2u);
    EXPECT_EQ(points[0].sets,
              (std::vector<std::string>{"scenario.architecture=a", "k.z=1", "k.x=1", "k.y=\"u\"", "scenario.seed=1"}));
    EXPECT_EQ(points[1].sets.back(), "scenario.seed=2");
    EXPECT_EQ(points[2].sets[3], "k.y=true");
    EXPECT_EQ(points[4].sets[2], "k.x=2.5");
    EXPECT_EQ(points[8].architecture, "b");
    EXPECT_EQ(points[15].id(), "00015");
}

TEST(SweepFile, ZipPairsTheValuesAndStudiesFollowEachOther) {
    const cnc::sim::SweepSpec spec = read_sweep_file(
        write("zip.toml",
              kHead + "[[study]]\nname = \"one\"\nmode = \"zip\"\nset = [\"k.w=3\"]\n"
                      "vary = [{ key = \"k.x\", from = 1, to = 3, step = 1 }, { key = \"k.y\", values = [7, 8, 9] }]\n"
                      "[[study]]\nname = \"two\"\nvary = [{ key = \"k.x\", from = 10, to = 1000, count = 3, "
                      "scale = \"log\" }]\n"));
    const std::vector<cnc::sim::SweepPoint> points = cnc::sim::expand_points(spec, "arch");
    ASSERT_EQ(points.size(), 3u + 3u);
    EXPECT_EQ(points[2].sets, (std::vector<std::string>{"scenario.architecture=arch", "k.w=3", "k.x=3", "k.y=9"}));
    EXPECT_FALSE(points[2].seed);
    EXPECT_EQ(points[4].sets, (std::vector<std::string>{"scenario.architecture=arch", "k.x=100"}));
    EXPECT_EQ(points[4].study, 1u);
}

TEST(SweepFile, WithoutVaryEachArchitectureRunsOverTheSeeds) {
    const cnc::sim::SweepSpec spec = read_sweep_file(write("seeds.toml", kHead + "seeds = [4, 9]\n"));
    const std::vector<cnc::sim::SweepPoint> points = cnc::sim::expand_points(spec, "arch");
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[1].sets, (std::vector<std::string>{"scenario.architecture=arch", "scenario.seed=9"}));
}

TEST(SweepFile, RefusalsNameTheLineAndTheKey) {
    const std::string vary = "vary = [{ key = \"k.x\", values = [1] }]\n";
    // kHead is lines 1 and 2: each mistake below is on line 3.
    const auto at_line_3 = [](const std::string& message, const std::string& key, const std::string& what) {
        EXPECT_NE(message.find(".toml:3: " + key), std::string::npos) << message << " / " << key;
        EXPECT_NE(message.find(what), std::string::npos) << message << " / " << what;
    };
    at_line_3(refusal("r1.toml", kHead + "vary = [{ key = \"k.x\", values = [] }]\n"), "vary[0].values", "empty list");
    at_line_3(refusal("r2.toml", kHead + "vary = [{ key = \"k.x\", from = 1, to = 5, step = 0 }]\n"), "vary[0].step",
              "step 0");
    at_line_3(refusal("r3.toml", kHead + "vary = [{ key = \"k.x\", from = 0, to = 5, count = 3, scale = \"log\" }]\n"),
              "vary[0].count", "two values > 0");
    at_line_3(refusal("r4.toml", kHead + "speed = 3\n" + vary), "speed", "unknown key");
    at_line_3(refusal("r5.toml", kHead + "seeds = []\n" + vary), "seeds", "empty list");
    at_line_3(refusal("r6.toml", kHead + "vary = [{ key = \"k.x\", values = [1], step = 2 }]\n"), "vary[0].step",
              "goes with a range");
    const std::string zip = refusal("r7.toml", kHead +
                                                   "mode = \"zip\"\nvary = [{ key = \"k.x\", values = [1, 2] }, "
                                                   "{ key = \"k.y\", values = [1] }]\n");
    EXPECT_NE(zip.find("r7.toml:4: vary"), std::string::npos) << zip;
    EXPECT_NE(zip.find("lists of one length"), std::string::npos) << zip;
    EXPECT_NE(refusal("r8.toml", "metrics = [\"/a\"]\n" + vary).find("r8.toml:1: scenario"), std::string::npos);
    EXPECT_NE(refusal("r9.toml", "scenario = \"s.toml\"\nmetrics = [\"a/b\"]\n" + vary).find("r9.toml:2: metrics"),
              std::string::npos);
    EXPECT_EQ(refusal("ok.toml", kHead + vary), "");
    const std::string search = "[search]\nkey = \"k.x\"\nfrom = 0\nto = 10\nholds = [{ metric = \"/a\", max = 0 }]\n";
    EXPECT_NE(refusal("s1.toml", kHead + search + "tolerance = 0\n").find("s1.toml:8: search.tolerance: must be > 0"),
              std::string::npos);
    EXPECT_NE(refusal("s2.toml", kHead + "seeds = 3\n" + search + "tolerance = 1\n").find("s2.toml:3: seeds"),
              std::string::npos);
    EXPECT_NE(refusal("s3.toml", kHead + search.substr(0, search.find("holds")) + "holds = [{ metric = \"/a\" }]\n" +
                                     "tolerance = 1\n")
                  .find("s3.toml:7: search.holds[0].max: give max, min or both"),
              std::string::npos);
}
