#include <gtest/gtest.h>

#include "common/bad_input.hpp"
#include "uart/core/uart_frame.hpp"

using cnc::Edge;
using cnc::TimePs;
using namespace cnc::uart;

namespace {

constexpr BitClock kFpga434{434, 50'000'000};  // seed 000 §4.2: 434 cycles of 50 MHz = 8.68 us
constexpr BitClock kCp2102At115200{208, 24'000'000};

bool same(const std::vector<Edge>& a, const std::vector<Edge>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].t_ps != b[i].t_ps || a[i].level != b[i].level) return false;
    }
    return true;
}

}  // namespace

TEST(UartFrame, AlternatingByteAt434CyclesOf50MHz) {
    constexpr TimePs b = 8'680'000;  // exact
    constexpr TimePs t0 = 1'000'000;
    // 0xAA LSB first: start 0, data 0 1 0 1 0 1 0 1, stop 1
    const std::vector<Edge> want{{t0, false},         {t0 + 2 * b, true}, {t0 + 3 * b, false}, {t0 + 4 * b, true},
                                 {t0 + 5 * b, false}, {t0 + 6 * b, true}, {t0 + 7 * b, false}, {t0 + 8 * b, true}};
    EXPECT_TRUE(same(frame_edges(0xAA, t0, kFpga434), want));
    EXPECT_EQ(frame_time_ps(kFpga434), 86'800'000);
}

TEST(UartFrame, ZeroByteIsOneLowStretchOfNineBits) {
    const std::vector<Edge> want{{0, false}, {9 * 8'680'000, true}};
    EXPECT_TRUE(same(frame_edges(0x00, 0, kFpga434), want));
    const std::vector<Edge> want24{{5, false}, {5 + 78'000'000, true}};  // 9 * 208 / 24 MHz = 78 us exactly
    EXPECT_TRUE(same(frame_edges(0x00, 5, kCp2102At115200), want24));
    EXPECT_TRUE(frame_edges(0xFF, 0, kFpga434).size() == 2);  // start bit only, then high
}

TEST(UartFrame, Cp2102BitBoundariesHaveNoDriftOver10000Bits) {
    // Exact rational time of boundary k: k * 208 / 24e6 s = k * 208e6 / 24 ps; the model may only round down.
    for (std::int64_t k = 0; k <= 10'000; ++k) {
        ASSERT_EQ(kCp2102At115200.bit_edge(k), k * 208'000'000 / 24) << "k=" << k;
    }
    EXPECT_EQ(kCp2102At115200.bit_edge(10'000), 86'666'666'666);
    // 1000 back-to-back frames placed at boundary 10*j: every edge within 1 ps of the exact time.
    for (std::int64_t j = 0; j < 1'000; ++j) {
        const auto edges = frame_edges(0x55, kCp2102At115200.bit_edge(10 * j), kCp2102At115200);
        ASSERT_EQ(edges.size(), 10U);  // 0x55: start 0, data 1 0 1 0 1 0 1 0, stop 1
        for (std::size_t k = 0; k < edges.size(); ++k) {
            const TimePs exact_floor = (10 * j + static_cast<std::int64_t>(k)) * 208'000'000 / 24;
            ASSERT_LE(std::abs(edges[k].t_ps - exact_floor), 1) << "frame " << j << " edge " << k;
        }
    }
}

TEST(UartFrame, MidBitIsHalfWayBetweenBoundaries) {
    EXPECT_EQ(kFpga434.mid_bit(0), 4'340'000);          // 217 cycles: seed 000 §4.2 HALF_BIT
    EXPECT_EQ(kFpga434.mid_bit(9), 82'460'000);         // 9.5 bits
    EXPECT_EQ(kCp2102At115200.mid_bit(9), 82'333'333);  // 9.5 * 208 / 24 MHz = 82.3333 us, rounded down
}

TEST(UartFrame, ParityAndTwoStopBits) {
    const FrameFormat e72{7, Parity::Even, 2};
    EXPECT_EQ(e72.bits_per_frame(), 11);
    // 0x03 in 7E2: start 0, data 1 1 0 0 0 0 0, parity (two ones -> even) 0, stop 1 1
    EXPECT_EQ(frame_bits(0x03, e72),
              (std::vector<bool>{false, true, true, false, false, false, false, false, false, true, true}));
    const FrameFormat o81{8, Parity::Odd, 1};
    EXPECT_EQ(frame_bits(0x03, o81).at(9), true);  // odd parity over two ones
    EXPECT_THROW(frame_bits(0x00, FrameFormat{9, Parity::None, 1}), cnc::BadInput);
    EXPECT_THROW(frame_bits(0x00, FrameFormat{8, Parity::None, 3}), cnc::BadInput);
}
