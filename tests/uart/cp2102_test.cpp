// SystemC tests of the CP2102 bridge (one TEST per process: ctest runs each separately).
#define SC_INCLUDE_DYNAMIC_PROCESSES
#include <gtest/gtest.h>

#include <cstdlib>
#include <systemc>
#include <vector>

#include "uart/core/line_receiver.hpp"
#include "uart/cp2102.hpp"

using cnc::TimePs;
using namespace cnc::uart;

namespace {

constexpr TimePs kMs = cnc::kPsPerMs;
// seed 000 §4.9: the worked motion packet
const std::vector<std::uint8_t> kPacket{0x01, 0x00, 0x00, 0x01, 0x40, 0xFF, 0xFF, 0xFF, 0x60, 0x04, 0xB0};

sc_core::sc_time at(TimePs t) {
    return sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t));
}
TimePs now_ps() {
    return static_cast<TimePs>(sc_core::sc_time_stamp().value());
}
void wait_until(TimePs t) {
    sc_core::wait(at(t - now_ps()));
}

// One 10-bit frame of the real CP2102 at 115200: 2080 clocks of 24 MHz, rounded down from the exact time.
TimePs cp_bits(std::int64_t k) {
    return k * 208'000'000 / 24;
}

}  // namespace

TEST(Cp2102, LoopbackPacketTimesFollowUsbFramesAndLatency) {
    sc_core::sc_signal<bool> line("line");
    Cp2102 cp("cp", Cp2102Config{});
    cp.txd(line);
    cp.rxd(line);
    std::vector<TimePs> data_event_times;
    sc_core::sc_spawn([&] {
        wait_until(300 * kMs + 400'000'000);  // t = 300.4 ms
        cp.usb_write(kPacket);
    });
    sc_core::sc_spawn([&] {
        for (;;) {
            sc_core::wait(cp.data_event());
            data_event_times.push_back(now_ps());
        }
    });
    sc_core::sc_start(at(310 * kMs));

    ASSERT_EQ(cp.tx_log().size(), 11U);
    for (std::size_t i = 0; i < 11; ++i) {
        const auto& b = cp.tx_log()[i];
        EXPECT_EQ(b.byte, kPacket[i]);
        EXPECT_EQ(b.t_write_ps, 300 * kMs + 400'000'000);
        EXPECT_EQ(b.t_usb_ps, 301 * kMs);                                                     // next USB frame start
        EXPECT_EQ(b.t_start_bit_ps, 301 * kMs + cp_bits(10 * static_cast<std::int64_t>(i)));  // back to back
        EXPECT_EQ(b.t_stop_end_ps, 301 * kMs + cp_bits(10 * static_cast<std::int64_t>(i) + 10));
    }
    EXPECT_EQ(cp.tx_log().back().t_stop_end_ps - cp.tx_log().front().t_start_bit_ps, 953'333'333);  // 110 bits

    ASSERT_EQ(cp.rx_log().size(), 11U);
    for (std::size_t i = 0; i < 11; ++i) {
        const auto& r = cp.rx_log()[i];
        EXPECT_EQ(r.byte, kPacket[i]);
        EXPECT_FALSE(r.framing_error);
        EXPECT_EQ(r.t_start_bit_ps, cp.tx_log()[i].t_start_bit_ps);
        // the receiver times the frame from the start edge with its own clock: equal within the 1 ps rounding
        EXPECT_LE(std::abs(r.t_stop_end_ps - cp.tx_log()[i].t_stop_end_ps), 1);
        // last stop bit ends at 301.953 ms -> IN transfer in the 302 ms frame -> + 1 ms driver latency
        EXPECT_EQ(r.t_host_visible_ps, 303 * kMs);
    }
    EXPECT_EQ(data_event_times, (std::vector<TimePs>{303 * kMs}));
    ASSERT_EQ(cp.in_waiting(), 11U);
    for (std::uint8_t want : kPacket) EXPECT_EQ(cp.read_byte(), std::optional<std::uint8_t>(want));
    EXPECT_EQ(cp.read_byte(), std::nullopt);
    EXPECT_EQ(cp.stats().framing_errors, 0);
}

TEST(Cp2102, ByteEndingAfterAFrameStartWaitsForTheNextFrame) {
    // Write at 0: frame 0 carries it out at t = 0; the byte's stop bit ends at 86.67 us -> IN frame at 1 ms.
    // A second packet written at 0.95 ms goes out at 1 ms and its bytes end after 1 ms -> IN frame at 2 ms.
    sc_core::sc_signal<bool> line("line");
    Cp2102Config cfg;
    cfg.usb_latency_ps = 250'000'000;  // 0.25 ms
    Cp2102 cp("cp", cfg);
    cp.txd(line);
    cp.rxd(line);
    sc_core::sc_spawn([&] {
        cp.usb_write(kPacket.data(), 1);
        wait_until(950'000'000);
        cp.usb_write(kPacket.data(), 2);
    });
    sc_core::sc_start(at(5 * kMs));
    ASSERT_EQ(cp.rx_log().size(), 3U);
    EXPECT_EQ(cp.tx_log()[0].t_start_bit_ps, 0);
    EXPECT_EQ(cp.rx_log()[0].t_host_visible_ps, 1 * kMs + 250'000'000);
    EXPECT_EQ(cp.tx_log()[1].t_start_bit_ps, 1 * kMs);
    EXPECT_EQ(cp.rx_log()[1].t_host_visible_ps, 2 * kMs + 250'000'000);
    EXPECT_EQ(cp.rx_log()[2].t_host_visible_ps, 2 * kMs + 250'000'000);
}

TEST(Cp2102, ResetInputBufferDropsOnlyWhatTheHostHolds) {
    sc_core::sc_signal<bool> line("line");
    Cp2102 cp("cp", Cp2102Config{});
    cp.txd(line);
    cp.rxd(line);
    std::size_t waiting_after_reset = 99;
    sc_core::sc_spawn([&] {
        cp.usb_write(kPacket);  // out at 0, visible at 1 ms frame + 1 ms = 2 ms
        wait_until(1'500'000'000);
        cp.usb_write(kPacket);  // out at 2 ms, ends 2.953 ms, visible at 3 ms + 1 ms = 4 ms
        wait_until(2'500'000'000);
        EXPECT_EQ(cp.in_waiting(), 11U);
        cp.reset_input_buffer();
        waiting_after_reset = cp.in_waiting();
    });
    sc_core::sc_start(at(5 * kMs));
    EXPECT_EQ(waiting_after_reset, 0U);
    EXPECT_EQ(cp.rx_log()[11].t_host_visible_ps, 4 * kMs);
    EXPECT_EQ(cp.in_waiting(), 11U);  // the second packet, in transit during the reset, arrived afterwards
}

TEST(Cp2102, TxFifoOverflowDropsAndCounts) {
    sc_core::sc_signal<bool> line("line");
    Cp2102 cp("cp", Cp2102Config{});
    cp.txd(line);
    cp.rxd(line);
    const std::vector<std::uint8_t> big(700, 0x55);
    sc_core::sc_spawn([&] { cp.usb_write(big); });
    sc_core::sc_start(at(60 * kMs));  // 640 frames take 55.47 ms
    EXPECT_EQ(cp.stats().tx_overflow_bytes, 60);
    ASSERT_EQ(cp.tx_log().size(), 640U);
    EXPECT_EQ(cp.tx_log().back().t_stop_end_ps, cp_bits(6'400));  // one burst, no drift
}

TEST(Cp2102, RxFifoOverflowsWhenUsbFramesAreRare) {
    // With 100 ms between IN transfers, the 640 looped-back bytes pile up in the 576-byte RX FIFO.
    sc_core::sc_signal<bool> line("line");
    Cp2102Config cfg;
    cfg.usb_frame_ps = 100 * kMs;
    Cp2102 cp("cp", cfg);
    cp.txd(line);
    cp.rxd(line);
    const std::vector<std::uint8_t> block(640, 0x3C);
    sc_core::sc_spawn([&] { cp.usb_write(block); });
    sc_core::sc_start(at(110 * kMs));
    EXPECT_EQ(cp.stats().tx_overflow_bytes, 0);
    EXPECT_EQ(cp.stats().rx_overflow_bytes, 64);
    EXPECT_EQ(cp.in_waiting(), 576U);
    EXPECT_EQ(cp.rx_log()[575].t_host_visible_ps, 101 * kMs);
    EXPECT_EQ(cp.rx_log()[576].t_host_visible_ps, -1);
}

TEST(Cp2102, ReceivesATwoPercentSlowSenderAndDropsASixPercentSlowOne) {
    sc_core::sc_signal<bool> to_pc("to_pc");
    sc_core::sc_signal<bool> from_pc("from_pc");
    Cp2102 cp("cp", Cp2102Config{});
    cp.txd(from_pc);
    cp.rxd(to_pc);
    to_pc.write(true);
    sc_core::sc_spawn([&] {
        // 115 384.6 Bd receiver; senders at 208 * 1.02 = 212 and 208 * 1.06 = 220 clocks of 24 MHz per bit.
        TimePs t = 1 * kMs;
        for (const std::int64_t ticks : {212, 220}) {
            for (const cnc::Edge& e : frame_edges(0x00, t, BitClock{ticks, 24'000'000})) {
                wait_until(e.t_ps);
                to_pc.write(e.level);
            }
            t += kMs;
        }
    });
    sc_core::sc_start(at(10 * kMs));
    ASSERT_EQ(cp.rx_log().size(), 2U);
    EXPECT_FALSE(cp.rx_log()[0].framing_error);
    EXPECT_EQ(cp.rx_log()[0].t_host_visible_ps, 3 * kMs);
    EXPECT_TRUE(cp.rx_log()[1].framing_error);
    EXPECT_EQ(cp.stats().framing_errors, 1);
    EXPECT_EQ(cp.in_waiting(), 1U);
    EXPECT_EQ(cp.read_byte(), std::optional<std::uint8_t>(0x00));
}

TEST(Cp2102, IdealBaudRunsAtTheRequestedRate) {
    sc_core::sc_signal<bool> line("line");
    Cp2102Config cfg;
    cfg.ideal_baud = true;
    Cp2102 cp("cp", cfg);
    cp.txd(line);
    cp.rxd(line);
    sc_core::sc_spawn([&] { cp.usb_write(kPacket); });
    sc_core::sc_start(at(3 * kMs));
    EXPECT_DOUBLE_EQ(cp.baud().actual_bd, 115'200.0);
    ASSERT_EQ(cp.tx_log().size(), 11U);
    EXPECT_EQ(cp.tx_log()[1].t_start_bit_ps, 86'805'555);
    EXPECT_EQ(cp.tx_log()[10].t_stop_end_ps, 954'861'111);  // 110 / 115200 s, rounded down
    EXPECT_EQ(cp.in_waiting(), 11U);
}

TEST(Cp2102, ThinnedTxLogKeepsEveryStrideThByteAndCountsThemAll) {
    sc_core::sc_signal<bool> line("line");
    Cp2102Config cfg;
    cfg.ideal_baud = true;
    Cp2102 cp("cp", cfg);
    cp.txd(line);
    cp.rxd(line);
    cp.thin_tx_log(1, 4);  // bytes 1, 5 and 9 of the 11
    sc_core::sc_spawn([&] { cp.usb_write(kPacket); });
    sc_core::sc_start(at(3 * kMs));
    // At exactly 115200 Bd a bit is 8,680,555.5 ps: byte j starts at the edge of bit 10 j, rounded down, and the
    // 11 back-to-back frames hold the line for 110 bits (954,861,111 ps, as IdealBaudRunsAtTheRequestedRate).
    ASSERT_EQ(cp.tx_log().size(), 3U);
    EXPECT_EQ(cp.tx_log()[0].byte, kPacket[1]);
    EXPECT_EQ(cp.tx_log()[0].t_start_bit_ps, 86'805'555);
    EXPECT_EQ(cp.tx_log()[1].byte, kPacket[5]);
    EXPECT_EQ(cp.tx_log()[1].t_start_bit_ps, 434'027'777);  // 50 bits
    EXPECT_EQ(cp.tx_log()[2].byte, kPacket[9]);
    EXPECT_EQ(cp.stats().tx_bytes, 11);
    EXPECT_EQ(cp.stats().tx_line_busy_ps, 954'861'111);
}

TEST(Cp2102, DroppedLogBytesLeaveTheOthersAndTheCounts) {
    sc_core::sc_signal<bool> line("line");
    Cp2102Config cfg;
    cfg.ideal_baud = true;
    Cp2102 cp("cp", cfg);
    cp.txd(line);
    cp.rxd(line);
    sc_core::sc_spawn([&] { cp.usb_write(kPacket); });
    sc_core::sc_start(at(3 * kMs));
    cp.drop_rx_log_before(6);
    cp.drop_tx_log_before(2);
    // Every byte still counted and numbered as before: 11 looped back, the kept ones at their indices.
    EXPECT_EQ(cp.rx_log().size(), 11U);
    EXPECT_EQ(cp.rx_log().first(), 6U);
    EXPECT_EQ(cp.rx_log()[6].byte, kPacket[6]);
    EXPECT_EQ(cp.tx_log().size(), 11U);
    EXPECT_EQ(cp.tx_log()[2].t_start_bit_ps, 173'611'111);  // 20 bits at exactly 115200 Bd, rounded down
    // The received frames' line time, the dropped ones included: 110 bits (954,861,111 ps, as
    // IdealBaudRunsAtTheRequestedRate), each frame timed by the receiver from its own start edge and rounded down
    // to the ps, so up to 1 ps short per frame.
    EXPECT_LE(cp.stats().rx_line_busy_ps, 954'861'111);
    EXPECT_GE(cp.stats().rx_line_busy_ps, 954'861'111 - 11);
}
