// Matching what a receiver framed against what was sent: cases built by hand, and a line garbled bit by bit and
// framed by the line receiver (uart/core/line_receiver.hpp) as an idle receiver frames it.
#include <gtest/gtest.h>

#include "uart/core/frame_match.hpp"
#include "uart/core/line_receiver.hpp"
#include "uart/core/uart_frame.hpp"

using namespace cnc;
using namespace cnc::uart;

namespace {

constexpr BitClock kClock{139, 16'000'000};  // 115 107.9 Bd: 16 MHz / 139
constexpr TimePs kTolPs = 62'500;            // one cycle of 16 MHz

SentFrame sent_at(TimePs t_ps, std::uint8_t byte) {
    return {t_ps, t_ps + frame_time_ps(kClock), byte};
}

// The line with each sent frame's bits, those of `inverted` (bit k of frame j: inverted[j] bit k) inverted, framed
// as an idle receiver does: a start at each fall of the idle line, the next search after its decision.
std::vector<ReceivedFrame> frame_line(const std::vector<SentFrame>& sent, const std::vector<std::uint32_t>& inverted) {
    EdgeLog line{"rx", true, {}};
    bool level = true;
    for (std::size_t j = 0; j < sent.size(); ++j) {
        const std::vector<bool> bits = frame_bits(sent[j].byte);
        for (std::size_t k = 0; k < bits.size(); ++k) {
            const bool b = bits[k] != (((inverted[j] >> k) & 1U) != 0);
            if (b != level) line.add(sent[j].t_start_ps + kClock.bit_edge(static_cast<std::int64_t>(k)), b);
            level = b;
        }
        if (!level) line.add(sent[j].t_end_ps, true);
        level = true;
    }
    std::vector<ReceivedFrame> got;
    TimePs busy_until = -1;
    for (const Edge& e : line.edges) {
        if (e.level || e.t_ps <= busy_until) continue;
        const RxFrame f = receive_frame(line, e.t_ps, kClock);
        if (f.status == RxStatus::FalseStart) continue;
        got.push_back({e.t_ps, f.byte, f.status == RxStatus::FramingError});
        busy_until = f.t_decision_ps;
    }
    return got;
}

}  // namespace

TEST(FrameMatch, EveryFrameAsSentOnACleanLine) {
    const std::vector<SentFrame> sent{sent_at(0, 0x41), sent_at(200'000'000, 0x06)};
    const FrameMatch m = match_frames(sent, frame_line(sent, {0, 0}), kTolPs);
    EXPECT_EQ(m.as_sent, 2U);
    EXPECT_EQ(m.wrong + m.lost + m.extra_frames + m.framing_flagged, 0U);
}

TEST(FrameMatch, ADataBitInvertedIsWrongAndAStopBitInvertedIsFlaggedWithItsDataRight) {
    const std::vector<SentFrame> sent{sent_at(0, 0x41), sent_at(200'000'000, 0x06)};
    // Frame 0: data bit 0 (frame bit 1); frame 1: the stop bit (frame bit 9).
    const FrameMatch m = match_frames(sent, frame_line(sent, {1U << 1, 1U << 9}), kTolPs);
    EXPECT_EQ(m.fate[0], FrameFate::Wrong);
    EXPECT_EQ(m.fate[1], FrameFate::AsSent);
    EXPECT_EQ(m.framing_flagged, 1U);
    EXPECT_EQ(m.extra_frames, 0U);
}

// 0x55 sends 0 1 0 1 0 1 0 1 0 1 (start, LSB first, stop): with the start bit high the receiver starts at data bit
// 1's fall, one bit later, frames the rest plus idle line, and the frame is wrong.
TEST(FrameMatch, AnInvertedStartBitMisframesTheByte) {
    const std::vector<SentFrame> sent{sent_at(0, 0x55)};
    const std::vector<ReceivedFrame> got = frame_line(sent, {1U});
    ASSERT_EQ(got.size(), 1U);
    EXPECT_EQ(got[0].t_start_ps, kClock.bit_edge(2));
    const FrameMatch m = match_frames(sent, got, kTolPs);
    EXPECT_EQ(m.fate[0], FrameFate::Wrong);
    EXPECT_EQ(m.extra_frames, 0U);
}

TEST(FrameMatch, ANothingFramedIsLostAndASecondFrameWithinOneIsExtra) {
    const std::vector<SentFrame> sent{sent_at(0, 0x00), sent_at(200'000'000, 0xFF), sent_at(400'000'000, 0x10)};
    const TimePs bit = kClock.bit_edge(1);
    const std::vector<ReceivedFrame> got{
        {0, 0x00, false}, {400'000'000, 0x10, false}, {400'000'000 + 5 * bit, 0xF0, true}};
    const FrameMatch m = match_frames(sent, got, kTolPs);
    EXPECT_EQ(m.fate[0], FrameFate::AsSent);
    EXPECT_EQ(m.fate[1], FrameFate::Lost);
    EXPECT_EQ(m.fate[2], FrameFate::AsSent);
    EXPECT_EQ(m.extra[2], 1U);
    EXPECT_EQ(m.extra_frames, 1U);
    EXPECT_EQ(m.framing_flagged, 1U);
    EXPECT_EQ(m.as_sent + m.wrong + m.lost, sent.size());
}

TEST(FrameMatch, AFrameStartingOffItsSentStartIsNotItsOwn) {
    const std::vector<SentFrame> sent{sent_at(0, 0x41)};
    EXPECT_EQ(match_frames(sent, {{kTolPs, 0x41, false}}, kTolPs).fate[0], FrameFate::AsSent);
    EXPECT_EQ(match_frames(sent, {{kTolPs + 1, 0x41, false}}, kTolPs).fate[0], FrameFate::Wrong);
    EXPECT_EQ(match_frames(sent, {{-kTolPs - 1, 0x41, false}}, kTolPs).extra_frames, 1U);
}
