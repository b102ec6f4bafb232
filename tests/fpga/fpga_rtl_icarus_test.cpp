// Our Verilog of seed 000's FPGA (models/fpga/rtl) under Icarus Verilog against the cycle-ticked reference: the same
// rx waveform (the mixed stream: every kind of packet, a packet and an init while busy, a dropped ACK, glitches, a
// framing error, partial packets cleared by the watchdog) must give the same edges on every output pin.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "fpga_test_support.hpp"
#include "reference_fpga.hpp"
#include "support/rtl_edges.hpp"
#include "support/test_path.hpp"

namespace cnc::fpga::test {
namespace {

void expect_rtl_as_reference(const UartWave& w, std::int64_t last_edge, const char* testbench = CNC_STREAM_TB) {
    const std::string rx = cnc::test::test_path("rx.txt");
    const std::string out = cnc::test::test_path("pins.txt");
    {
        std::ofstream f(rx);
        for (const Edge& e : w.changes()) f << e.t_ps << ' ' << (e.level ? 1 : 0) << '\n';
    }
    const std::string cmd = std::string(CNC_VVP) + " -n " + testbench + " +rx=" + rx + " +out=" + out +
                            " +edges=" + std::to_string(last_edge) + " > " + cnc::test::test_path("vvp.log") + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const auto rtl = cnc::test::read_rtl_edges(out, kCyclePs);
    const auto reference = ref::run_reference(FpgaConfig{}, w.changes(), last_edge);
    expect_same_edges(reference, rtl, {"tx", "dir_x", "step_x", "dir_y", "step_y", "laser", "busy"});
    EXPECT_GT(reference.at("step_x").edges.size(), 10U);  // the stream moved something
}

TEST(FpgaRtlIcarus, MixedStreamFromA50MHzSenderAsTheReference) {
    UartWave w = sync_sender();
    const std::int64_t last = mixed_stream(w);
    expect_rtl_as_reference(w, last);
}

TEST(FpgaRtlIcarus, MixedStreamFromTheCp2102AsTheReference) {
    UartWave w = cp2102_sender();
    const std::int64_t last = mixed_stream(w);
    expect_rtl_as_reference(w, last);
}

// step_gen with the sequential divider (DIVIDER = 1, for FPGAs without room for the single-clock one): the same
// pins. The stream's packets, up to before the watchdog's part (36 ms).
TEST(FpgaRtlIcarus, TheSequentialDividerGivesTheSameEdges) {
    UartWave w = cp2102_sender();
    (void)mixed_stream(w);
    expect_rtl_as_reference(w, edge_of(36 * kMs), CNC_STREAM_SEQ_TB);
}

}  // namespace
}  // namespace cnc::fpga::test
