#include <gtest/gtest.h>

#include <initializer_list>

#include "uart/core/line_receiver.hpp"

using cnc::EdgeLog;
using cnc::TimePs;
using namespace cnc::uart;

namespace {

constexpr BitClock kRx{434, 50'000'000};  // receiver: seed 000 §4.2, 115 207 Bd

// Back-to-back frames sent at `tx` from t = 0.
EdgeLog line_of(std::initializer_list<std::uint8_t> bytes, BitClock tx) {
    EdgeLog line{"rx", true, {}};
    TimePs t = 0;
    for (std::uint8_t b : bytes) {
        for (const cnc::Edge& e : frame_edges(b, t, tx)) line.add(e.t_ps, e.level);
        t += frame_time_ps(tx);
    }
    return line;
}

}  // namespace

TEST(LineReceiver, DecodesAtMatchedRate) {
    const EdgeLog line = line_of({0xA5}, kRx);
    const RxFrame f = receive_frame(line, 0, kRx);
    EXPECT_EQ(f.status, RxStatus::Ok);
    EXPECT_EQ(f.byte, 0xA5);
    EXPECT_EQ(f.t_decision_ps, 82'460'000);  // 9.5 bits
    EXPECT_EQ(f.t_stop_end_ps, 86'800'000);
}

TEST(LineReceiver, DecodesASenderTwoPercentFastOrSlow) {
    for (const BitClock tx : {BitClock{425, 50'000'000}, BitClock{443, 50'000'000}}) {  // -2.07 %, +2.07 % bit time
        for (const std::uint8_t b : {0x00, 0xFF, 0xA5, 0x5A, 0x01, 0x80}) {
            const EdgeLog line = line_of({b, static_cast<std::uint8_t>(~b)}, tx);
            const RxFrame f = receive_frame(line, 0, kRx);
            EXPECT_EQ(f.status, RxStatus::Ok) << "tx ticks " << tx.ticks_per_bit << " byte " << int(b);
            EXPECT_EQ(f.byte, b);
            const RxFrame g = receive_frame(line, frame_time_ps(tx), kRx);
            EXPECT_EQ(g.status, RxStatus::Ok);
            EXPECT_EQ(g.byte, static_cast<std::uint8_t>(~b));
        }
    }
}

TEST(LineReceiver, FramingErrorAtSixPercentMismatch) {
    // Sender 6 % slow (460 cycles): the stop-bit sample at 9.5 receiver bits = 8.96 sender bits lands in the
    // last data bit, low for 0x00.
    const RxFrame slow = receive_frame(line_of({0x00}, BitClock{460, 50'000'000}), 0, kRx);
    EXPECT_EQ(slow.status, RxStatus::FramingError);
    // Sender 6 % fast (408 cycles), frames back to back: the stop sample (4123 cycles) falls in the next
    // start bit (from 4080 cycles).
    const RxFrame fast = receive_frame(line_of({0xFF, 0xFF}, BitClock{408, 50'000'000}), 0, kRx);
    EXPECT_EQ(fast.status, RxStatus::FramingError);
}

TEST(LineReceiver, GlitchIsAFalseStartAndParityIsChecked) {
    EdgeLog glitch{"rx", true, {{1'000, false}, {2'000'000, true}}};  // 2 us low: gone by the mid-start sample
    EXPECT_EQ(receive_frame(glitch, 1'000, kRx).status, RxStatus::FalseStart);

    const FrameFormat e81{8, Parity::Even, 1};
    EdgeLog line{"rx", true, {}};
    for (const cnc::Edge& e : frame_edges(0x07, 0, kRx, e81)) line.add(e.t_ps, e.level);
    EXPECT_EQ(receive_frame(line, 0, kRx, e81).status, RxStatus::Ok);
    EXPECT_EQ(receive_frame(line, 0, kRx, FrameFormat{8, Parity::Odd, 1}).status, RxStatus::ParityError);
}
