// packet_decoder byte state machine, uart_rx/uart_tx cycle offsets, and the rx line history.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "common/crc16.hpp"
#include "fpga/core/line_history.hpp"
#include "fpga/core/packet_decoder_core.hpp"
#include "fpga/core/uart_timing.hpp"
#include "uart_wave.hpp"

namespace cnc::fpga {
namespace {

using Completed = PacketDecoderCore::Completed;

std::vector<Completed> feed_bytes(PacketDecoderCore& d, const std::vector<std::uint8_t>& bytes) {
    std::vector<Completed> out;
    for (const std::uint8_t b : bytes) out.push_back(d.on_byte(b));
    return out;
}

TEST(PacketDecoderCore, InitAndMotionPacketsComplete) {
    PacketDecoderCore d(18'750'000);
    const auto init = feed_bytes(d, test::init_packet(9'375'000, 1'000));
    EXPECT_EQ(init.back(), Completed::Init);
    EXPECT_EQ(std::count(init.begin(), init.end(), Completed::None), 8);
    EXPECT_EQ(d.init().num_x, 9'375'000U);
    EXPECT_EQ(d.init().num_y, 1'000U);
    EXPECT_FALSE(d.timeout_active());
    const auto motion = feed_bytes(d, test::motion_packet(3, -7, 123'456, 65'535));
    EXPECT_EQ(motion.back(), Completed::Motion);
    EXPECT_EQ(d.motion().motion, 3);
    EXPECT_EQ(d.motion().steps_x, -7);
    EXPECT_EQ(d.motion().steps_y, 123'456);
    EXPECT_EQ(d.motion().feed, 65'535);
    EXPECT_EQ(d.byte_count(), 0);
}

TEST(PacketDecoderCore, MotionUsesOnlyTheLowTwoBitsOfByteZero) {
    PacketDecoderCore d(18'750'000);
    // 0xFE, the manual laser packet of seed 000 §2.6, is not in the appendix decoder: it starts a motion packet.
    feed_bytes(d, {0xFE, 0, 0, 0, 1, 0, 0, 0, 1, 0, 10});
    EXPECT_EQ(d.motion().motion, 2);
}

TEST(PacketDecoderCore, TimeoutClearsAPartialPacketAndKeepsOutputs) {
    PacketDecoderCore d(18'750'000);
    feed_bytes(d, test::motion_packet(1, 5, 6, 7));
    feed_bytes(d, {0xFF, 1, 2});
    EXPECT_TRUE(d.timeout_active());
    EXPECT_EQ(d.byte_count(), 3);
    d.on_timeout();
    EXPECT_EQ(d.byte_count(), 0);
    EXPECT_FALSE(d.timeout_active());
    EXPECT_EQ(d.motion().steps_y, 6);  // fields keep their last values
    EXPECT_EQ(feed_bytes(d, test::motion_packet(0, 1, 1, 1)).back(), Completed::Motion);
}

// The packet check: a packet followed by its CRC-16/CCITT-FALSE, computed here over the bytes as sent (the catalogue
// law is common/crc16.hpp's own test), bit 7 of the motion byte the alternating sequence bit.
std::vector<std::uint8_t> checked(std::vector<std::uint8_t> bytes, bool sequence = false) {
    if (sequence) bytes[0] = static_cast<std::uint8_t>(bytes[0] | PacketDecoderCore::kSequenceBit);
    const std::uint16_t crc = crc16(bytes.data(), bytes.size());
    bytes.push_back(static_cast<std::uint8_t>(crc >> 8U));
    bytes.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
    return bytes;
}

// With the ramp (fpga.ramp) the init packet carries the ramp's acceleration and start registers after the
// numerators, big-endian: 17 bytes, and the registers keep their reset values until one arrives.
TEST(PacketDecoderCore, WithTheRampTheInitPacketCarriesItsRegisters) {
    PacketDecoderCore d(18'750'000, false, true, RampDefaults{18'014, 68'719, std::nullopt});
    EXPECT_EQ(d.init().ramp_accel, 18'014U);
    EXPECT_EQ(d.init().ramp_start, 68'719U);
    const std::vector<std::uint8_t> init = {0xFF, 0x01, 0x1E, 0x1A, 0x30, 0x00, 0x8F, 0x0D, 0x18,
                                            0x00, 0x00, 0x46, 0x5E, 0x00, 0x01, 0x0C, 0x8F};
    const auto done = feed_bytes(d, init);
    EXPECT_EQ(std::count(done.begin(), done.end(), Completed::None), 16);  // not done at the seed's 9th byte
    EXPECT_EQ(done.back(), Completed::Init);
    EXPECT_EQ(d.init().num_x, 18'750'000U);
    EXPECT_EQ(d.init().num_y, 9'375'000U);
    EXPECT_EQ(d.init().ramp_accel, 0x465EU);
    EXPECT_EQ(d.init().ramp_start, 0x10C8FU);
    EXPECT_EQ(feed_bytes(d, test::motion_packet(1, 320, -160, 1200)).back(), Completed::Motion);

    PacketDecoderCore with_check(18'750'000, true, true, RampDefaults{});
    const auto checked_done = feed_bytes(with_check, checked(init));
    EXPECT_EQ(std::count(checked_done.begin(), checked_done.end(), Completed::None), 18);
    EXPECT_EQ(checked_done.back(), Completed::Init);
    EXPECT_EQ(with_check.init().ramp_start, 0x10C8FU);
}

// With the S-curve the jerk register follows: 21 bytes.
TEST(PacketDecoderCore, WithTheSCurveTheInitPacketCarriesItsJerk) {
    PacketDecoderCore d(18'750'000, false, true, RampDefaults{18'014, 68'719, 77'371'252});
    EXPECT_EQ(d.init().ramp_jerk, 77'371'252U);
    const std::vector<std::uint8_t> init = {0xFF, 0x01, 0x1E, 0x1A, 0x30, 0x00, 0x8F, 0x0D, 0x18, 0x00, 0x00,
                                            0x46, 0x5E, 0x00, 0x01, 0x0C, 0x8F, 0x09, 0x39, 0x27, 0xA9};
    const auto done = feed_bytes(d, init);
    EXPECT_EQ(std::count(done.begin(), done.end(), Completed::None), 20);  // not done at the trapezoid's 17th
    EXPECT_EQ(done.back(), Completed::Init);
    EXPECT_EQ(d.init().ramp_accel, 0x465EU);
    EXPECT_EQ(d.init().ramp_start, 0x10C8FU);
    EXPECT_EQ(d.init().ramp_jerk, 0x093927A9U);
    EXPECT_EQ(feed_bytes(d, test::motion_packet(1, 320, -160, 1200)).back(), Completed::Motion);
}

TEST(PacketDecoderCore, CheckedPacketsCompleteAfterTheirCrc) {
    PacketDecoderCore d(18'750'000, true);
    const auto init = feed_bytes(d, checked(test::init_packet(9'375'000, 1'000)));
    ASSERT_EQ(init.size(), 11U);
    EXPECT_EQ(std::count(init.begin(), init.end(), Completed::None), 10);
    EXPECT_EQ(init.back(), Completed::Init);
    EXPECT_EQ(d.init().num_y, 1'000U);
    const auto motion = feed_bytes(d, checked(test::motion_packet(3, -7, 123'456, 65'535), true));
    ASSERT_EQ(motion.size(), 13U);
    EXPECT_EQ(motion.back(), Completed::Motion);
    EXPECT_EQ(d.motion().motion, 3);  // the sequence bit is not part of the motion code
    EXPECT_EQ(d.motion().steps_x, -7);
    EXPECT_EQ(d.motion().feed, 65'535);
    EXPECT_EQ(d.byte_count(), 0);
    EXPECT_FALSE(d.timeout_active());
}

// With the laser's PWM the high time follows FeedRate, big-endian: 13 bytes, 15 with the check; not done at the
// seed's 11th byte.
TEST(PacketDecoderCore, WithTheLaserPwmTheMotionPacketCarriesTheHighTime) {
    std::vector<std::uint8_t> packet = test::motion_packet(1, 320, -160, 1200);
    packet.push_back(0x0C);  // 3200 clocks: half of a 6400-clock period
    packet.push_back(0x80);
    PacketDecoderCore d(18'750'000, false, true, std::nullopt, true);
    const auto done = feed_bytes(d, packet);
    EXPECT_EQ(std::count(done.begin(), done.end(), Completed::None), 12);
    EXPECT_EQ(done.back(), Completed::Motion);
    EXPECT_EQ(d.motion().feed, 1200);
    EXPECT_EQ(d.motion().laser_high, 3200);
    EXPECT_EQ(d.motion().steps_y, -160);

    PacketDecoderCore with_check(18'750'000, true, true, std::nullopt, true);
    const auto checked_done = feed_bytes(with_check, checked(packet));
    ASSERT_EQ(checked_done.size(), 15U);
    EXPECT_EQ(std::count(checked_done.begin(), checked_done.end(), Completed::None), 14);
    EXPECT_EQ(checked_done.back(), Completed::Motion);
    EXPECT_EQ(with_check.motion().laser_high, 3200);
}

TEST(PacketDecoderCore, EverySingleBitErrorInACheckedPacketIsABadCrcAndNoMove) {
    const std::vector<std::uint8_t> good = checked(test::motion_packet(1, 320, 160, 1200));
    for (std::size_t byte = 0; byte < good.size(); ++byte) {
        for (int bit = 0; bit < 8; ++bit) {
            PacketDecoderCore d(18'750'000, true);
            std::vector<std::uint8_t> hit = good;
            hit[byte] ^= static_cast<std::uint8_t>(1U << bit);
            EXPECT_EQ(feed_bytes(d, hit).back(), Completed::BadCrc) << byte << ":" << bit;
            EXPECT_EQ(d.motion().steps_x, 0);  // the fields keep their reset values
        }
    }
}

TEST(PacketDecoderCore, AMoveSentAgainWithItsSequenceBitIsARepeat) {
    PacketDecoderCore d(18'750'000, true);
    EXPECT_EQ(feed_bytes(d, checked(test::motion_packet(1, 10, 0, 800), false)).back(), Completed::Motion);
    EXPECT_EQ(feed_bytes(d, checked(test::motion_packet(1, 10, 0, 800), false)).back(), Completed::Repeat);
    EXPECT_EQ(feed_bytes(d, checked(test::motion_packet(1, 20, 0, 800), true)).back(), Completed::Motion);
    EXPECT_EQ(d.motion().steps_x, 20);
    EXPECT_EQ(feed_bytes(d, checked(test::motion_packet(1, 20, 0, 800), true)).back(), Completed::Repeat);
    EXPECT_EQ(feed_bytes(d, checked(test::motion_packet(1, 30, 0, 800), false)).back(), Completed::Motion);
    // A bad CRC passes nothing on: the next packet with the other bit is still new.
    PacketDecoderCore e(18'750'000, true);
    std::vector<std::uint8_t> hit = checked(test::motion_packet(1, 10, 0, 800), false);
    hit[4] ^= 0x01;
    EXPECT_EQ(feed_bytes(e, hit).back(), Completed::BadCrc);
    EXPECT_EQ(feed_bytes(e, checked(test::motion_packet(1, 10, 0, 800), false)).back(), Completed::Motion);
}

TEST(PacketDecoderCore, WithoutTheWatchdogALeftoverByteShiftsTheNextPacket) {
    // Seed 000's motion packets carry no sync marker. 3 stale bytes + a new packet complete after 8 new bytes.
    PacketDecoderCore d(18'750'000);
    feed_bytes(d, {0x01, 0x00, 0x00});
    const auto r = feed_bytes(d, test::motion_packet(1, 5, 3, 3000));
    EXPECT_EQ(r[7], Completed::Motion);
    EXPECT_EQ(d.motion().steps_x, 0x0000'0100);  // 00 00 | 01 00: the new motion byte lands in StepsX
    EXPECT_EQ(d.motion().steps_y, 0x0000'0500);
    EXPECT_EQ(d.motion().feed, 0);
    EXPECT_EQ(d.byte_count(), 3);
}

TEST(UartTiming, ReceiverSamplesMidBitFromTheStartDetection) {
    const UartRxTiming t{FpgaConfig{}};
    EXPECT_EQ(t.start_check, 217);
    EXPECT_EQ(t.bit(0), 217 + 434);
    EXPECT_EQ(t.bit(7), 217 + 8 * 434);
    EXPECT_EQ(t.stop, 217 + 9 * 434);  // 4123: rx_valid edge
    EXPECT_EQ(t.idle_after_stop(), 4124);
    EXPECT_EQ(t.idle_after_glitch(), 218);
}

TEST(UartTiming, TransmitterFrameOfTheAck) {
    const UartTxFrame f = uart_tx_frame(0xAA, FpgaConfig{});
    EXPECT_EQ(f.busy_rise, 1);
    const std::vector<std::int64_t> cycles{2, 870, 1304, 1738, 2172, 2606, 3040, 3474};
    ASSERT_EQ(f.tx_changes.size(), cycles.size());
    for (std::size_t i = 0; i < cycles.size(); ++i) {
        EXPECT_EQ(f.tx_changes[i].cycle, cycles[i]);
        EXPECT_EQ(f.tx_changes[i].level, i % 2 == 1);  // 0xAA = 0,1,0,1,... LSB first after the start bit
    }
    EXPECT_EQ(f.busy_fall, 4341);
    EXPECT_EQ(f.idle_from, 4342);
}

TEST(LineHistory, AnEdgeSamplesTheLevelStrictlyBeforeIt) {
    LineHistory h(true);
    h.add(40'000, false);
    h.add(40'000, false);  // no change
    h.add(50'000, true);
    EXPECT_TRUE(h.level_before(40'000));
    EXPECT_FALSE(h.level_before(40'001));
    EXPECT_FALSE(h.level_before(50'000));
    EXPECT_TRUE(h.level_before(50'001));
    EXPECT_EQ(h.first_change_at_or_after(40'001).value(), 50'000);
    EXPECT_FALSE(h.first_change_at_or_after(50'001).has_value());
    h.forget_before(45'000);
    EXPECT_FALSE(h.level_before(45'000));
    EXPECT_TRUE(h.level_before(60'000));
}

}  // namespace
}  // namespace cnc::fpga
