// USART0 of the ATmega328P model at line level (datasheet §20): frame timing on TXD, the UDRE0/TXC0 timing the
// firmware sees, and reception at the AVR's own bit clock from senders off its baud rate. UBRR0 = 16, U2X0 = 0
// (seed 003 §5.3.1): 16 * 17 = 272 cycles per bit (58 823.5 Bd), 2720 cycles per 8N1 frame.
#include "avr_test_support.hpp"
#include "uart/core/uart_frame.hpp"
#include "uart/cp2102.hpp"

using namespace cnc::avr;
using namespace cnc::avr::test;
using cnc::Edge;
using cnc::TimePs;

namespace {

constexpr Cycle kBitCycles = 272;
constexpr Cycle kFrameCycles = 10 * kBitCycles;  // 1 start + 8 data + 1 stop; stock libsimavr uses 11 bits
const cnc::uart::BitClock kAvrClock{kBitCycles, 16'000'000};
// The receiver decides at the middle of the stop bit: 9.5 bits = 2584 cycles after the start edge.
constexpr Cycle kDecisionCycles = 2584;

// The firmware's poll loop (lds 2 + sbrs 1 + rjmp 2 cycles) reads the flag 0..4 cycles after it is set, then
// lds + skipping sbrs take 4 more cycles before its marker `out`.
void expect_seen_after(Cycle marker, Cycle flag_set) {
    EXPECT_GE(marker - flag_set, 4);
    EXPECT_LE(marker - flag_set, 8);
}

struct LineFrame {
    TimePs t_start_ps;
    std::uint8_t byte;
    TimePs bit_ps;  // any bit time: the sender's clock
};

// Drives `line` with 8N1 frames (one writer process).
void drive_frames(sc_core::sc_signal<bool>& line, std::vector<LineFrame> frames) {
    sc_core::sc_spawn([&line, frames] {
        for (const auto& [t0, byte, bit_ps] : frames) {
            for (const Edge& e : cnc::uart::frame_edges(byte, t0, cnc::uart::BitClock{bit_ps, cnc::kPsPerSec})) {
                sc_core::wait(at_ps(e.t_ps - now_ps()));
                line.write(e.level);
            }
        }
    });
}

}  // namespace

TEST(AvrUsart, TransmitsTenBitFramesBackToBackAtTheBitClock) {
    // UBRR0L written at a: the baud rate generator restarts, bit-clock ticks at a + 272 k. UDR0 = 0x55 written
    // at w1 into the idle transmitter: the shift register loads it at the next tick s1 (start bit, UDRE0 set
    // again). The firmware writes 0xA3 and 0x0F as soon as it sees UDRE0; each loads when the previous stop
    // bit ends: s2 = s1 + 2720, s3 = s2 + 2720. TXC0 is set when the last stop bit ends, at s3 + 2720.
    AvrBench b(config_with_usart_logs(AVR_FW_USART_TX_ELF));
    b.run_until_ps(cnc::kPsPerMs);
    const Cycle a = first_rise(b, "dir_x") + 1;
    const Cycle w1 = first_rise(b, "dir_y") + 1;
    const Cycle s1 = a + ((w1 - a) / kBitCycles + 1) * kBitCycles;
    const Cycle s2 = s1 + kFrameCycles;
    const Cycle s3 = s2 + kFrameCycles;
    const Cycle txc = s3 + kFrameCycles;
    EXPECT_GT(s1, w1);
    EXPECT_LE(s1 - w1, kBitCycles);

    std::vector<Edge> want;
    for (const auto& [byte, s] : {std::pair<std::uint8_t, Cycle>{0x55, s1}, {0xA3, s2}, {0x0F, s3}})
        for (const Edge& e : cnc::uart::frame_edges(byte, ps_of(s), kAvrClock)) want.push_back(e);
    const auto& got = b.log("txd").edges;
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_EQ(got[i].t_ps, want[i].t_ps) << i;
        EXPECT_EQ(got[i].level, want[i].level) << i;
    }
    EXPECT_EQ(got.front().t_ps, s1 * kCyclePs);
    EXPECT_EQ(got.back().t_ps, (s3 + 9 * kBitCycles) * kCyclePs);  // 0x0F: its bit 7 = 0, then the stop bit

    const auto& log = b.avr.chip().usart().tx_log();
    ASSERT_EQ(log.size(), 3U);
    EXPECT_EQ(log[0].write_cycle, w1);
    EXPECT_EQ(log[0].start_cycle, s1);
    EXPECT_EQ(log[1].start_cycle, s2);
    EXPECT_EQ(log[2].start_cycle, s3);
    EXPECT_EQ(log[2].end_cycle, txc);
    EXPECT_EQ(log[1].start_cycle - log[0].start_cycle, 2720);  // 10 bit times, not stock libsimavr's 11 (2992)

    // What the firmware saw: UDRE0 at s1 (the first byte moved on), at s2, and TXC0 at s3 + 2720.
    const auto m = edge_cycles(b, "en_y");
    ASSERT_EQ(m.size(), 3U);
    expect_seen_after(m[0], s1);
    expect_seen_after(m[1], s2);
    expect_seen_after(m[2], txc);
    EXPECT_EQ(b.avr.stats().usart.tx_frames, 3);
    EXPECT_EQ(b.avr.stats().usart.tx_ignored_writes, 0);
    EXPECT_TRUE(b.avr.stopped());
}

TEST(AvrUsart, ReceivesFromTheCp2102AtItsOwnBaudRate) {
    // The CP2102 set to 57 600 Bd really sends at 24 MHz / 417 = 57 553.96 Bd: 17.375 us = 278 AVR cycles per
    // bit, 2.2 % slower than the AVR's 58 823.5 Bd. The AVR samples at its own 272-cycle bit clock from the
    // start edge; the stop bit is sampled at 9.5 * 272 = 2584 cycles, inside the sender's stop bit (which
    // starts at 9 * 278 = 2502): no framing error. RXC0 rises at that decision cycle.
    AvrBench b(config_with_usart_logs(AVR_FW_USART_ECHO_ELF));
    cnc::uart::Cp2102 cp("cp", cnc::uart::Cp2102Config{57'600});
    cp.txd(b.rxd);
    cp.rxd(*b.signals[kTxdLine]);
    sc_core::sc_spawn([&cp] {
        sc_core::wait(at_ps(500 * cnc::kPsPerUs));
        cp.usb_write(std::vector<std::uint8_t>{'X'});  // leaves the CP2102 at 1 ms: the receiver is still off
        sc_core::wait(at_ps(2500 * cnc::kPsPerUs));
        cp.usb_write(std::vector<std::uint8_t>{'G', '1', '\n'});  // at 3 ms: out in the 3 ms USB frame
    });
    b.run_until_ps(8 * cnc::kPsPerMs);

    const Cycle rx_on = first_rise(b, "dir_x");
    ASSERT_EQ(cp.tx_log().size(), 4U);
    EXPECT_LT(cycle_of(cp.tx_log()[0].t_stop_end_ps), rx_on);
    const auto& rx = b.avr.chip().usart().rx_log();
    ASSERT_EQ(rx.size(), 4U);
    EXPECT_FALSE(rx[0].stored);  // 'X' arrived while RXEN0 = 0
    EXPECT_EQ(rx[0].byte, 'X');
    const auto markers = edge_cycles(b, "dir_y");
    ASSERT_EQ(markers.size(), 3U);
    const std::string sent = "G1\n";
    for (std::size_t i = 1; i < 4; ++i) {
        const Cycle start = cycle_of(cp.tx_log()[i].t_start_bit_ps);
        EXPECT_EQ(start, 48'000 + 278 * 10 * static_cast<Cycle>(i - 1));  // USB frame at 3 ms, then 2780 apart
        EXPECT_EQ(rx[i].byte, static_cast<std::uint8_t>(sent[i - 1]));
        EXPECT_EQ(rx[i].status, cnc::uart::RxStatus::Ok);
        EXPECT_TRUE(rx[i].stored);
        EXPECT_EQ(rx[i].start_cycle, start);
        EXPECT_EQ(rx[i].decision_cycle, start + kDecisionCycles);
        expect_seen_after(markers[i - 1], start + kDecisionCycles);
    }
    const AvrCoreStats s = b.avr.stats();
    EXPECT_EQ(s.usart.rx_lost_disabled, 1);
    EXPECT_EQ(s.usart.rx_frames, 3);
    EXPECT_EQ(s.usart.rx_framing_errors, 0);
    EXPECT_EQ(s.rx_late_decisions, 0);
    // The echo, sent at 58 823.5 Bd, reaches the CP2102 intact (its receiver runs at 57 553.96 Bd).
    ASSERT_EQ(cp.rx_log().size(), 3U);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(cp.rx_log()[i].byte, static_cast<std::uint8_t>(sent[i]));
        EXPECT_FALSE(cp.rx_log()[i].framing_error);
    }
}

TEST(AvrUsart, ASenderSixPercentSlowGivesAFramingError) {
    // 0x41 ('A', bit 7 = 0) from senders off the AVR's 17 us bit (times from the start edge; the AVR samples
    // bit k at (k + 0.5) * 17 us):
    //   6 % slow (18.02 us): the stop-bit sample at 161.5 us falls in the sender's bit 8 (data bit 7, low,
    //     144.16..162.18 us): FE0 is set, the firmware echoes 0xFE;
    //   5 % slow (17.85 us): the sample falls in the stop bit (160.65..178.5 us): 0x41 arrives intact;
    //   6 % fast (15.98 us): the stop bit is sampled after the frame (idle, high), so no framing error, but
    //     bit 7 is sampled in the sender's stop bit (143.82..159.8 us) and reads 1: 0xC1.
    AvrBench b(config_with_usart_logs(AVR_FW_USART_ECHO_ELF));
    drive_frames(b.rxd, {{3 * cnc::kPsPerMs, 0x41, 18'020'000},
                         {4 * cnc::kPsPerMs, 0x41, 17'850'000},
                         {5 * cnc::kPsPerMs, 0x41, 15'980'000}});
    b.run_until_ps(7 * cnc::kPsPerMs);

    const auto& rx = b.avr.chip().usart().rx_log();
    ASSERT_EQ(rx.size(), 3U);
    EXPECT_EQ(rx[0].status, cnc::uart::RxStatus::FramingError);
    EXPECT_EQ(rx[1].status, cnc::uart::RxStatus::Ok);
    EXPECT_EQ(rx[1].byte, 0x41);
    EXPECT_EQ(rx[2].status, cnc::uart::RxStatus::Ok);
    EXPECT_EQ(rx[2].byte, 0xC1);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(rx[i].decision_cycle, 48'000 + 16'000 * static_cast<Cycle>(i) + kDecisionCycles);

    const auto& tx = b.avr.chip().usart().tx_log();
    ASSERT_EQ(tx.size(), 3U);
    EXPECT_EQ(tx[0].byte, 0xFE);  // the firmware read FE0 = 1 before UDR0
    EXPECT_EQ(tx[1].byte, 0x41);
    EXPECT_EQ(tx[2].byte, 0xC1);
    EXPECT_EQ(b.avr.stats().usart.rx_framing_errors, 1);
    EXPECT_EQ(b.avr.stats().usart.rx_frames, 3);
}
