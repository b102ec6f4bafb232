// The plug-in builder and loader (models/rtl) with Verilator on small designs written here: a design clocked through
// the plug-in counting as its Verilog says it must, its fixed point detected, its parameters set, the cache used,
// Verilator's errors and a missing port refused.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/bad_input.hpp"
#include "counter_design.hpp"
#include "rtl/plugin_build.hpp"
#include "rtl/plugin_load.hpp"

namespace cnc::rtl {
namespace {

namespace fs = std::filesystem;

// A folder of its own per test, and the cache in it.
class RtlPlugin : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("cncsim_rtl_plugin_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
        setenv("CNCSIM_RTL_CACHE", (m_dir / "cache").c_str(), 1);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(m_dir / name) << text;
        return (m_dir / name).string();
    }

    fs::path m_dir;
};

TEST_F(RtlPlugin, ClocksTheDesignAndFindsItsFixedPoint) {
    const PluginSpec spec = counter_spec(write("counter.v", kCounter));
    const BuiltPlugin built = build_plugin(spec);
    EXPECT_FALSE(built.from_cache);
    EXPECT_EQ(built.observed_present, (std::vector<bool>{true, false}));
    EXPECT_TRUE(built.rising_edge_only);  // one always @(posedge clk): one evaluation per clock period
    const std::unique_ptr<RtlModel> model = load_model(built);
    // Disabled: the count holds, every edge the same state.
    model->set_input(0, 0);
    EXPECT_EQ(model->run(10), 10U);
    EXPECT_EQ(model->value(0), 0U);
    EXPECT_TRUE(model->settled());
    // Enabled: each edge changes count, so each run stops after one edge.
    model->set_input(0, 1);
    EXPECT_FALSE(model->settled());
    for (std::uint64_t expected = 1; expected <= 5; ++expected) {
        EXPECT_EQ(model->run(100), 1U);
        EXPECT_EQ(model->value(0), expected);
        EXPECT_EQ(model->value(2), expected - 1);  // shadow: the count one edge before
    }
    EXPECT_EQ(model->value(1), 1U);  // at_limit
    // shadow catches up on the next edge, then nothing changes: a fixed point.
    EXPECT_EQ(model->run(100), 1U);
    EXPECT_EQ(model->value(2), 5U);
    EXPECT_EQ(model->run(100), 100U);
    EXPECT_TRUE(model->settled());
}

TEST_F(RtlPlugin, ParametersReachTheDesignAndTheCacheServesItAgain) {
    PluginSpec spec = counter_spec(write("counter.v", kCounter));
    spec.parameters = {{"LIMIT", "2"}};
    const BuiltPlugin first = build_plugin(spec);
    const BuiltPlugin again = build_plugin(spec);
    EXPECT_TRUE(again.from_cache);
    EXPECT_EQ(again.library, first.library);
    const std::unique_ptr<RtlModel> model = load_model(again);
    model->set_input(0, 1);
    EXPECT_EQ(model->run(100), 1U);
    EXPECT_EQ(model->run(100), 1U);
    EXPECT_EQ(model->value(1), 1U);  // at the limit of 2
    // An edited source is another design.
    write("counter.v", std::string(kCounter) + "// edited\n");
    EXPECT_FALSE(build_plugin(spec).from_cache);
}

// A design that also acts on the falling edge is evaluated on both: counted the same on each edge, the falls keep up
// with the rises (they would stay at 0 if the falling edge were skipped).
TEST_F(RtlPlugin, AFallingEdgeBlockIsEvaluatedOnItsEdge) {
    PluginSpec spec = counter_spec(write("edges.v", R"(module edges(
    input wire clk, input wire enable, output reg [7:0] count, output reg [7:0] falls);
    initial begin count = 8'd0; falls = 8'd0; end
    always @(posedge clk) if (enable) count <= count + 8'd1;
    always @(negedge clk) if (enable) falls <= falls + 8'd1;
endmodule
)"));
    spec.top_module = "edges";
    spec.outputs = {{"count", 8}, {"falls", 8}};
    spec.observed.clear();
    const BuiltPlugin built = build_plugin(spec);
    EXPECT_FALSE(built.rising_edge_only);
    const std::unique_ptr<RtlModel> model = load_model(built);
    model->set_input(0, 1);
    for (std::uint64_t edges = 1; edges <= 4; ++edges) {
        EXPECT_EQ(model->run(100), 1U);
        EXPECT_EQ(model->value(0), edges);
        EXPECT_EQ(model->value(1), edges);
    }
}

TEST_F(RtlPlugin, AVerilatorErrorShowsItsFileAndLine) {
    const std::string file = write("broken.v", "module counter(input wire clk);\n  wire a = ;\nendmodule\n");
    try {
        (void)build_plugin(counter_spec(file));
        FAIL() << "a design that does not parse was built";
    } catch (const BadInput& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("test.toml: fpga.rtl_top: Verilator could not build module counter:"), std::string::npos)
            << what;
        EXPECT_NE(what.find("%Error: " + file + ":2:"), std::string::npos) << what;
    }
    EXPECT_FALSE(fs::exists(fs::path(rtl_cache_dir())) && !fs::is_empty(fs::path(rtl_cache_dir())));
}

TEST_F(RtlPlugin, AMissingPortIsRefusedBeforeCompiling) {
    const std::string file =
        write("counter.v", "module counter(input wire clk, input wire enable, output reg [7:0] count);\n"
                           "  always @(posedge clk) count <= count + {7'd0, enable};\nendmodule\n");
    EXPECT_THROW((void)build_plugin(counter_spec(file)), BadInput);
}

}  // namespace
}  // namespace cnc::rtl
