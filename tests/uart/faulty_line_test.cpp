// A CP2102 sends bytes through a FaultyLine to its own receiver: what arrives is what the draw says, bit by bit.
// The receiver is the CP2102's line decoder (samples at mid-bit), not the fault model, so a window of inversion
// placed off its bit would show as another byte.
#define SC_INCLUDE_DYNAMIC_PROCESSES
#include <gtest/gtest.h>

#include <algorithm>
#include <systemc>
#include <vector>

#include "common/sc_time.hpp"
#include "uart/cp2102.hpp"
#include "uart/faulty_line.hpp"

using cnc::TimePs;
using namespace cnc::uart;

namespace {

constexpr int kFrameBits = 10;  // 8N1
constexpr std::uint32_t kStartBit = 1U;
constexpr std::uint32_t kStopBit = 1U << 9U;

sc_core::sc_time at(TimePs t) {
    return sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t));
}

// A CP2102 whose TXD reaches its own RXD through a faulty wire.
struct Loopback {
    Loopback(const LineFaultRates& rates, std::uint64_t seed, std::uint64_t line_id)
        : line("line", rates, seed, line_id, cp.baud().bit_clock()) {
        cp.txd(sent);
        line.in(sent);
        line.out(seen);
        cp.rxd(seen);
    }
    sc_core::sc_signal<bool> sent{"sent", true};
    sc_core::sc_signal<bool> seen{"seen", true};
    Cp2102 cp{"cp", Cp2102Config{}};
    FaultyLine line;
};

}  // namespace

TEST(FaultyLine, EachFrameArrivesAsItsDrawSays) {
    const LineFaultRates rates{0.02, 0.02};
    Loopback loop(rates, 5, 3);
    Cp2102& cp = loop.cp;
    const FaultyLine& line = loop.line;
    constexpr int kBytes = 2000;
    // One byte per USB frame: idle between frames, so a misframed byte cannot run into the next.
    sc_core::sc_spawn([&] {
        for (int k = 0; k < kBytes; ++k) {
            const auto b = static_cast<std::uint8_t>(k * 37 + 11);
            cp.usb_write(&b, 1);
            sc_core::wait(at(cnc::kPsPerMs));
        }
    });
    sc_core::sc_start(at((kBytes + 5) * cnc::kPsPerMs));

    const LineFaultDraw draw(rates, 5, 3);
    ASSERT_EQ(cp.tx_log().size(), static_cast<std::size_t>(kBytes));
    EXPECT_EQ(line.stats().frames, static_cast<std::uint64_t>(kBytes));
    std::size_t r = cp.rx_log().first();
    int clean = 0, changed = 0, framing = 0, lost = 0;
    for (int k = 0; k < kBytes; ++k) {
        const auto& tx = cp.tx_log()[static_cast<std::size_t>(k)];
        const FrameFault f = draw.frame(static_cast<std::uint64_t>(k), kFrameBits);
        // The receiver's frames that start within this byte's millisecond.
        std::vector<Cp2102::RxByte> got;
        for (; r < cp.rx_log().size() && cp.rx_log()[r].t_start_bit_ps < tx.t_start_bit_ps + cnc::kPsPerMs; ++r) {
            got.push_back(cp.rx_log()[r]);
        }
        if (f.lost) {
            EXPECT_TRUE(got.empty()) << "frame " << k;
            ++lost;
            continue;
        }
        if ((f.inverted_bits & kStartBit) != 0) continue;  // no start edge there: the receiver starts later, or not
        ASSERT_EQ(got.size(), 1U) << "frame " << k;
        EXPECT_EQ(got[0].t_start_bit_ps, tx.t_start_bit_ps) << "frame " << k;
        if ((f.inverted_bits & kStopBit) != 0) {
            EXPECT_TRUE(got[0].framing_error) << "frame " << k;
            ++framing;
            continue;
        }
        EXPECT_FALSE(got[0].framing_error) << "frame " << k;
        const auto data_mask = static_cast<std::uint8_t>((f.inverted_bits >> 1U) & 0xFFU);
        EXPECT_EQ(got[0].byte, static_cast<std::uint8_t>(tx.byte ^ data_mask)) << "frame " << k;
        (data_mask != 0 ? changed : clean)++;
    }
    // Every kind of fate came up (about 2 % lost, 2 % of frames with a stop bit hit, 16 % with a data bit).
    EXPECT_GT(lost, 10);
    EXPECT_GT(framing, 10);
    EXPECT_GT(changed, 100);
    EXPECT_GT(clean, 1000);
    EXPECT_EQ(line.stats().frames_lost, static_cast<std::uint64_t>(lost));
}

// A receiver that runs ahead of the simulation time (the Verilog in the loop, models/fpga/rtl_loop.hpp) asks the
// line until when its output stays as it is, then runs to the first 20 ns clock edge after that time unless the
// output changes first. Every change must come at or after the time promised: an inverted bit changes the output
// where the sender's pin does not, and a sender's edge at a bit boundary may change it twice in one instant (the
// CP2102 starts a frame right after the last one's stop bit a delta late). Back-to-back frames (four bytes a USB
// frame) at a high bit error rate hit every bit position.
TEST(FaultyLine, PromisesEveryChangeOfItsOutput) {
    const LineFaultRates rates{0.05, 0.02};
    Loopback loop(rates, 7, 0);
    Cp2102& cp = loop.cp;
    FaultyLine& line = loop.line;
    sc_core::sc_signal<bool>& seen = loop.seen;
    constexpr int kUsbFrames = 300;
    constexpr TimePs kClockPs = 20'000;
    sc_core::sc_spawn([&] {
        for (int k = 0; k < kUsbFrames; ++k) {
            const std::uint8_t b[4] = {static_cast<std::uint8_t>(k), 0x55, 0xAA, 0x0F};
            cp.usb_write(b, 4);
            sc_core::wait(at(cnc::kPsPerMs));
        }
    });
    int changes = 0, early = 0;
    sc_core::sc_spawn([&] {
        TimePs promised = 0;
        for (;;) {
            const TimePs now = cnc::now_ps();
            if (seen.event()) {
                ++changes;
                if (now < promised) ++early;
            }
            promised = std::max(now, line.out_quiet_until(cp.txd_quiet_until()));
            const TimePs next_edge = (promised / kClockPs + 1) * kClockPs;
            sc_core::wait(at(next_edge - now), seen.value_changed_event());
        }
    });
    sc_core::sc_start(at((kUsbFrames + 5) * cnc::kPsPerMs));

    EXPECT_GT(line.stats().frames_hit, 100U);
    EXPECT_GT(changes, 1000);
    EXPECT_EQ(early, 0);
}
