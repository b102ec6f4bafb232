// The fault tally of fpga-uart: each packet step_gen saw laid against the one the host was sending.
#include <gtest/gtest.h>

#include "architectures/fpga_uart/packet_faults.hpp"

using namespace cnc::sim::fpga_uart;

namespace {

cnc::fpga::MotionFields move(std::int32_t x, std::int32_t y) {
    return {1, x, y, 800};
}

}  // namespace

TEST(PacketFaults, EachRecordIsLaidAgainstThePacketInFlight) {
    // Four packets taken at 0, 10, 20, 30 ms; the second never arrives (a lost byte), the third arrives with a bit
    // of steps_x inverted (bit 10: +1024), the fourth arrives twice (a repeat), and one record precedes every packet.
    const std::vector<HostPacket> sent = {
        {0, 1, move(100, 0)}, {10, 2, move(0, 50)}, {20, 3, move(-30, 30)}, {30, 4, move(5, 5)}};
    const std::vector<FpgaPacket> received = {{-1, true, move(7, 7)},           {2, true, move(100, 0)},
                                              {22, true, move(-30 + 1024, 30)}, {32, true, move(5, 5)},
                                              {35, true, move(5, 5)},           {36, false, move(9, 9)}};
    const PacketFaults f = packet_faults(sent, received);
    EXPECT_EQ(f.sent, 4);
    EXPECT_EQ(f.executed_as_sent, 2);  // 1 and 4
    EXPECT_EQ(f.executed_wrong, 1);    // 3
    EXPECT_EQ(f.lost, 1);              // 2
    EXPECT_EQ(f.extra, 2);             // 4 again, and the record before any packet
    EXPECT_EQ(f.ignored, 1);
    ASSERT_EQ(f.silent.size(), 1U);
    EXPECT_EQ(f.silent[0].segment, 3);
    EXPECT_EQ(f.silent[0].gcode_line, 3);
    EXPECT_EQ(f.silent[0].error_steps, (StepPair{1024, 0}));
    // Executed: 7+100+994+5+5 = 1111 X, 7+0+30+5+5 = 47 Y; sent: 75 X, 85 Y.
    EXPECT_EQ(f.job_end_error_steps, (StepPair{1111 - 75, 47 - 85}));
}

// Only bits [1:0] of the motion byte reach step_gen and laser_ctrl: an inverted bit above them changes nothing.
TEST(PacketFaults, AMotionBitTheDecoderDropsIsNoCorruption) {
    const std::vector<HostPacket> sent = {{0, 0, {1, 10, 10, 800}}};
    const PacketFaults high = packet_faults(sent, {{1, true, {1 | 0x40, 10, 10, 800}}});
    EXPECT_EQ(high.executed_as_sent, 1);
    EXPECT_EQ(high.executed_wrong, 0);
    const PacketFaults low = packet_faults(sent, {{1, true, {0, 10, 10, 800}}});
    EXPECT_EQ(low.executed_wrong, 1);
    EXPECT_EQ(low.silent[0].error_steps, (StepPair{0, 0}));  // a rapid instead of a cut: right place, laser off
}
