// The packet queue's rules (fpga/core/packet_queue_core.hpp) and its frame (common/queue_protocol.hpp): go-back-N
// over numbers modulo 32 with at most 16 in flight, and the 2-byte status, its bits written out by hand.
#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <vector>

#include "common/crc16.hpp"
#include "common/queue_protocol.hpp"
#include "fpga/core/packet_decoder_core.hpp"
#include "fpga/core/packet_queue_core.hpp"

namespace cnc::fpga {
namespace {

namespace qp = queue_protocol;
using Taken = PacketQueueCore::Taken;

MotionFields numbered(int seq, std::int32_t steps_x = 32) {
    MotionFields f;
    f.motion = 1;
    f.steps_x = steps_x;
    f.feed = 3000;
    f.seq = static_cast<std::uint8_t>(seq);
    return f;
}

TEST(PacketQueueCore, TakesTheNextNumberWhileASlotIsFreeAndRefusesTheRest) {
    PacketQueueCore q(2);
    EXPECT_EQ(q.on_packet(numbered(1)), Taken::Refused);  // 0 is next
    EXPECT_EQ(q.on_packet(numbered(0)), Taken::Queued);
    EXPECT_EQ(q.on_packet(numbered(1)), Taken::Queued);
    EXPECT_EQ(q.on_packet(numbered(2)), Taken::Refused);  // no slot
    EXPECT_EQ(q.status(false), (qp::Status{2, 0, false, false}));
    MotionFields out;
    ASSERT_TRUE(q.pop(out));
    EXPECT_EQ(out.seq, 0);
    EXPECT_EQ(q.status(false), (qp::Status{2, 1, true, false}));
    EXPECT_EQ(q.on_packet(numbered(2)), Taken::Queued);
    ASSERT_TRUE(q.pop(out));
    ASSERT_TRUE(q.pop(out));
    EXPECT_EQ(out.seq, 2);
    EXPECT_FALSE(q.pop(out));
    q.on_move_done();
    EXPECT_EQ(q.status(true), (qp::Status{3, 2, false, true}));
    EXPECT_EQ(q.queued(), 3U);
    EXPECT_EQ(q.refused(), 2U);
}

// Numbers up to 16 behind the next are packets taken already, sent again because their status was lost: answered,
// never queued twice; 17 behind is 15 ahead, and refused.
TEST(PacketQueueCore, AWindowOfSixteenBehindIsAnsweredAcrossTheWrap) {
    PacketQueueCore q(16);
    MotionFields out;
    for (int n = 0; n < 40; ++n) {
        ASSERT_EQ(q.on_packet(numbered(n % 32)), Taken::Queued) << n;
        ASSERT_TRUE(q.pop(out));
    }
    EXPECT_EQ(q.status(false).next_seq, 8);  // 40 mod 32
    EXPECT_EQ(q.on_packet(numbered(7)), Taken::Again);
    EXPECT_EQ(q.on_packet(numbered(24)), Taken::Again);    // 16 behind, across the wrap
    EXPECT_EQ(q.on_packet(numbered(23)), Taken::Refused);  // 17 behind: 15 ahead
    EXPECT_EQ(q.on_packet(numbered(9)), Taken::Refused);
    EXPECT_EQ(q.answered_again(), 2U);
    EXPECT_TRUE(q.empty());
}

TEST(PacketQueueCore, DepthOutsideOneToSixteenIsRefused) {
    EXPECT_THROW(PacketQueueCore(0), std::invalid_argument);
    EXPECT_THROW(PacketQueueCore(17), std::invalid_argument);
}

TEST(QueueProtocol, StatusBytesAreTaggedElevenAndTen) {
    EXPECT_EQ(qp::encode({1, 4, true, false}), (std::array<std::uint8_t, 2>{0xE4, 0x81}));   // 111 00100, 100 00001
    EXPECT_EQ(qp::encode({31, 16, false, true}), (std::array<std::uint8_t, 2>{0xD0, 0xBF}));  // 110 10000, 101 11111
    for (int next = 0; next < 32; ++next) {
        for (int free = 0; free <= 16; ++free) {
            for (const bool flag : {false, true}) {
                const qp::Status s{next, free, flag, !flag};
                const auto b = qp::encode(s);
                qp::StatusReader r;
                bool stray = true;
                EXPECT_FALSE(r.feed(b[0], stray));
                EXPECT_FALSE(stray);
                const auto back = r.feed(b[1], stray);
                ASSERT_TRUE(back);
                EXPECT_EQ(*back, s);
            }
        }
    }
}

TEST(QueueProtocol, AByteLostOrOutOfPlaceIsStrayAndTheNextStatusIsRead) {
    qp::StatusReader r;
    bool stray = false;
    EXPECT_FALSE(r.feed(0x81, stray));  // a byte 1 without its byte 0
    EXPECT_TRUE(stray);
    EXPECT_FALSE(r.feed(0xE4, stray));
    EXPECT_FALSE(stray);
    EXPECT_FALSE(r.feed(0xE3, stray));  // a second byte 0: the first lost its byte 1
    EXPECT_TRUE(stray);
    EXPECT_EQ(r.feed(0x82, stray), (qp::Status{2, 3, true, false}));
    EXPECT_FALSE(r.feed(0x55, stray));  // the seed's NAK fits no status
    EXPECT_TRUE(stray);
}

// The number rides in bits 6:2 of the motion byte: bits 1:0 stay the motion step_gen and laser_ctrl read, and bit 7
// stays 0, so that no numbered motion byte is the init marker 0xFF.
TEST(QueueProtocol, TheNumberLeavesTheMotionBitsAndNeverMakesTheInitMarker) {
    for (int seq = 0; seq < 32; ++seq) {
        for (std::uint8_t motion = 0; motion < 4; ++motion) {
            const std::uint8_t b = qp::with_seq(motion, seq);
            EXPECT_EQ(b & 0x3, motion);
            EXPECT_EQ(qp::seq_of(b), seq);
            EXPECT_EQ(b & 0x80, 0);
        }
    }
    EXPECT_EQ(qp::with_seq(0x01, 1), 0x05);
    EXPECT_EQ(qp::with_seq(0x02, 31), 0x7E);
}

// With the queue the numbers tell a repeat, not the packet check's alternating bit: two packets with the same bit 7
// both complete as motion, each with its number.
TEST(PacketDecoderCore, WithTheQueueTheSequenceBitIsNotRead) {
    PacketDecoderCore d(18'750'000, true, false);
    const std::vector<std::uint8_t> body{0x05, 0, 0, 0, 32, 0, 0, 0, 0, 0x0B, 0xB8};
    std::vector<std::uint8_t> packet = body;
    const std::uint16_t crc = crc16(packet.data(), packet.size());
    packet.push_back(static_cast<std::uint8_t>(crc >> 8U));
    packet.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
    for (int n = 0; n < 2; ++n) {
        PacketDecoderCore::Completed last = PacketDecoderCore::Completed::None;
        for (const std::uint8_t b : packet) last = d.on_byte(b);
        EXPECT_EQ(last, PacketDecoderCore::Completed::Motion) << n;
        EXPECT_EQ(d.motion().seq, 1);
        EXPECT_EQ(d.motion().motion, 1);
        EXPECT_EQ(d.motion().feed, 3000);
    }
}

}  // namespace
}  // namespace cnc::fpga
