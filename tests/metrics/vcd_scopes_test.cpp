// The VCD's hardware blocks: one scope each under the top scope, written as IEEE 1364 §18.2 nests them
// ($scope module NAME $end ... $upscope $end), and the names `cncsim analyze` accepts for a signal in them.
#include <gtest/gtest.h>

#include <sstream>

#include "common/bad_input.hpp"
#include "metrics/vcd/vcd_reader.hpp"
#include "metrics/vcd/vcd_writer.hpp"

namespace cnc::metrics {
namespace {

VcdSignal in_block(const std::string& name, const std::string& block) {
    VcdSignal s{name, false, std::nullopt};
    s.scope = block;
    return s;
}

TEST(MetricsVcdScopes, OneScopePerBlockInTheOrderTheBlocksFirstCome) {
    std::ostringstream out;
    // A block's signals need not be listed together: each block's scope holds all of them.
    VcdWriter w(out, 1'000,
                {in_block("uart_rx", "link"), in_block("step_x", "driver_x"), in_block("uart_tx", "link"),
                 in_block("dir_x", "driver_x"), in_block("marker", "")},
                "test");
    w.change(2'000, 1, true);
    w.finish(3'000);
    EXPECT_NE(out.str().find("$scope module cncsim $end\n"
                             "$scope module link $end\n$var wire 1 ! uart_rx $end\n$var wire 1 # uart_tx $end\n"
                             "$upscope $end\n"
                             "$scope module driver_x $end\n$var wire 1 \" step_x $end\n$var wire 1 % dir_x $end\n"
                             "$upscope $end\n"
                             "$var wire 1 & marker $end\n"
                             "$upscope $end\n$enddefinitions $end\n"),
              std::string::npos)
        << out.str();
    // The identifiers stay those of the signals' indices: the change of signal 1 is step_x's.
    EXPECT_NE(out.str().find("#2000\n1\"\n"), std::string::npos) << out.str();
}

TEST(MetricsVcdScopes, NamesAreUniqueInTheFileNotOnlyInTheirScope) {
    // sigrok-cli names its channels by the variable's name alone: two "step" would be one channel to it.
    EXPECT_THROW(check_vcd_signals(1'000, {in_block("step", "driver_x"), in_block("step", "driver_y")}, "t"),
                 BadInput);
    EXPECT_THROW(check_vcd_signals(1'000, {in_block("step_x", "driver x")}, "t"), BadInput);
    EXPECT_NO_THROW(check_vcd_signals(1'000, {in_block("step_x", "driver_x"), in_block("step_y", "driver_y")}, "t"));
}

const char* const kScoped =
    "$timescale 1 ns $end\n"
    "$scope module cncsim $end\n"
    "$scope module driver_x $end\n$var wire 1 ! step_x $end\n$upscope $end\n"
    "$scope module a $end\n$var wire 1 \" step $end\n$upscope $end\n"
    "$scope module b $end\n$var wire 1 # step $end\n$upscope $end\n"
    "$upscope $end\n$enddefinitions $end\n#0\n$dumpvars\n0!\n0\"\n0#\n$end\n#5\n1!\n#7\n1#\n";

TEST(MetricsVcdScopes, ASignalIsFoundByItsNameOrItsScopePath) {
    std::istringstream in(kScoped);
    const VcdContents vcd = read_vcd(in, "t.vcd");
    for (const char* name : {"step_x", "driver_x.step_x", "cncsim.driver_x.step_x"}) {
        const EdgeLog* log = find_vcd_signal(vcd, name);
        ASSERT_NE(log, nullptr) << name;
        EXPECT_EQ(log->rising(), std::vector<TimePs>{5'000}) << name;
    }
    // A path names whole scopes: "x.step_x" is not the tail of driver_x.step_x.
    EXPECT_EQ(find_vcd_signal(vcd, "x.step_x"), nullptr);
    EXPECT_EQ(find_vcd_signal(vcd, "driver_y.step_x"), nullptr);
    // "step" is in two scopes: ambiguous, found only with its scope.
    EXPECT_EQ(find_vcd_signal(vcd, "step"), nullptr);
    ASSERT_NE(find_vcd_signal(vcd, "b.step"), nullptr);
    EXPECT_EQ(find_vcd_signal(vcd, "b.step")->rising(), std::vector<TimePs>{7'000});
}

}  // namespace
}  // namespace cnc::metrics
