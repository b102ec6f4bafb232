// Verilator's port declarations read and a design's ports checked against the list the simulation drives and reads
// (models/rtl/verilated_ports.hpp), with messages naming the port.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/bad_input.hpp"
#include "counter_design.hpp"
#include "rtl/verilated_ports.hpp"

namespace cnc::rtl {
namespace {

TEST(VerilatedPorts, ReadsVerilatorsDeclarations) {
    const std::string header = "    VL_IN8(&clk,0,0);\n    VL_IN16(&feed,15,0);\n    VL_OUT(&steps,31,0);\n"
                               "    VL_OUT64(&wide,39,0);\n    VL_INW(&bus,69,0,3);\n";
    const std::vector<VerilatedPort> ports = parse_verilated_ports(header);
    ASSERT_EQ(ports.size(), 5U);
    EXPECT_EQ(ports[1].name, "feed");
    EXPECT_EQ(ports[1].width, 16);
    EXPECT_TRUE(ports[1].input);
    EXPECT_EQ(ports[2].width, 32);
    EXPECT_FALSE(ports[2].input);
    EXPECT_EQ(ports[3].width, 40);
    EXPECT_EQ(ports[4].width, 70);
}

TEST(VerilatedPorts, DeclaredParametersEachWithItsKeyword) {
    const std::vector<std::string> names = declared_parameters(
        "module m #(parameter A = 1, parameter [7:0] B = 8'h2, parameter integer C=3) ();\n"
        "localparam D = 4;\n  parameter signed E = -1;\nendmodule\n");
    EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "C", "E"}));
}

TEST(VerilatedPorts, EveryMismatchNamesThePort) {
    PluginSpec spec = counter_spec("counter.v");
    const std::vector<VerilatedPort> good{{"clk", 1, true}, {"enable", 1, true}, {"count", 8, false},
                                          {"at_limit", 1, false}, {"spare", 4, false}};
    EXPECT_NO_THROW(check_ports(spec, good));
    auto message = [&](std::vector<VerilatedPort> ports) {
        try {
            check_ports(spec, ports);
        } catch (const BadInput& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    std::vector<VerilatedPort> ports = good;
    ports.erase(ports.begin() + 3);
    EXPECT_EQ(message(ports),
              "test.toml: fpga.rtl_top: module counter has no port at_limit: expected output at_limit (1 bit)");
    ports = good;
    ports[2].width = 16;
    EXPECT_EQ(message(ports),
              "test.toml: fpga.rtl_top: port count of module counter is output count (16 bits): expected output "
              "count (8 bits)");
    ports = good;
    ports[1].input = false;
    EXPECT_EQ(message(ports),
              "test.toml: fpga.rtl_top: port enable of module counter is output enable (1 bit): expected input "
              "enable (1 bit)");
    ports = good;
    ports.push_back({"reset", 1, true});
    EXPECT_EQ(message(ports),
              "test.toml: fpga.rtl_top: input reset of module counter is not driven by the simulation (its inputs: "
              "clk, enable)");
}

TEST(VerilatedPorts, AnOptionalInputMayBeMissingAndIsDrivenWhenPresent) {
    PluginSpec spec = counter_spec("counter.v");
    spec.inputs.push_back({"hold", 1, true});
    const std::vector<VerilatedPort> without{
        {"clk", 1, true}, {"enable", 1, true}, {"count", 8, false}, {"at_limit", 1, false}};
    EXPECT_NO_THROW(check_ports(spec, without));
    std::vector<VerilatedPort> with = without;
    with.push_back({"hold", 1, true});
    EXPECT_NO_THROW(check_ports(spec, with));
    with.back().width = 2;
    EXPECT_THROW(check_ports(spec, with), BadInput);
}

}  // namespace
}  // namespace cnc::rtl
