// UsartUnit against the datasheet (§20): baud rate, TX frame and flag timing, the receive buffer.
#include <gtest/gtest.h>

#include <vector>

#include "avr/core/usart_unit.hpp"

using namespace cnc::avr;
using cnc::uart::RxFrame;
using cnc::uart::RxStatus;

namespace {

class Recorder : public UsartSink {
public:
    void usart_flags(Cycle c) override {
        if (unit == nullptr) return;
        const std::uint8_t a = unit->ucsra() & 0xE0;  // RXC0 TXC0 UDRE0
        if (a != last) flag_changes.emplace_back(c, a);
        last = a;
    }
    void usart_txd(Cycle c, bool level) override { txd.emplace_back(c, level); }
    const UsartUnit* unit = nullptr;
    std::uint8_t last = 0x20;
    std::vector<std::pair<Cycle, std::uint8_t>> flag_changes;
    std::vector<std::pair<Cycle, bool>> txd;
};

struct Fixture {
    explicit Fixture(bool keep_logs = true) : u(rec, keep_logs) { rec.unit = &u; }  // most tests read the logs
    Recorder rec;
    UsartUnit u;
    void setup_58823(Cycle c) {  // seed 003 §5.3.1: UBRR0 = 16, U2X0 = 0, RXEN0 | TXEN0, 8N1
        u.write_ubrrh(c, 0);
        u.write_ubrrl(c, 16);
        u.write_ucsrb(c, 0x18);
    }
};

RxFrame frame(std::uint8_t b, RxStatus st = RxStatus::Ok) {
    RxFrame f;
    f.byte = b;
    f.status = st;
    return f;
}

}  // namespace

TEST(AvrUsartUnit, BaudRateFromUbrrAndU2x) {
    Fixture f;
    EXPECT_EQ(f.u.ucsra(), 0x20);  // reset: UDRE0 (§20.11.2)
    EXPECT_EQ(f.u.ucsrc(), 0x06);  // reset: 8 data bits
    f.u.write_ubrrl(0, 16);
    EXPECT_EQ(f.u.bit_cycles(), 272);  // 16 * (16 + 1): 58 823.5 Bd
    f.u.write_ucsra(0, 0x02);          // U2X0, written after UBRR0 (simavr 1.6 would keep 272)
    EXPECT_EQ(f.u.bit_cycles(), 136);
    f.u.write_ubrrh(0, 0x01);
    EXPECT_EQ(f.u.bit_cycles(), 8 * (256 + 16 + 1));
    EXPECT_DOUBLE_EQ(f.u.bit_clock(16'000'000).baud(), 16e6 / (8.0 * 273));
    f.u.write_ucsrc(0, 0x2E);  // UPM0 = 10 (even), USBS0, 8 bits
    EXPECT_EQ(f.u.format().parity, cnc::uart::Parity::Even);
    EXPECT_EQ(f.u.format().stop_bits, 2);
    EXPECT_EQ(f.u.format().bits_per_frame(), 12);
}

TEST(AvrUsartUnit, TransmitterTimingAndFlags) {
    // UBRR0L written at 100: bit clock ticks at 100 + 272 k. UDR0 written at 150 loads at 372; a second byte
    // written at 400 waits in the buffer and loads at 372 + 2720; TXC0 at the end of its stop bit.
    Fixture f;
    f.setup_58823(100);
    f.u.write_udr(150, 0x00);
    EXPECT_EQ(f.u.ucsra() & 0x20, 0);  // UDRE0 cleared by the write
    f.u.advance_to(371);
    EXPECT_EQ(f.u.ucsra() & 0x20, 0);
    f.u.advance_to(372);
    EXPECT_EQ(f.u.ucsra() & 0x20, 0x20);  // moved to the shift register
    f.u.write_udr(400, 0xFF);
    f.u.write_udr(401, 0x12);  // UDRE0 = 0: ignored (§20.6.1)
    f.u.advance_to(20'000);
    const std::vector<std::pair<Cycle, bool>> want{{372, false},
                                                   {372 + 9 * 272, true},  // 0x00: start + 8 zero bits, stop bit
                                                   {3092, false},
                                                   {3092 + 272, true}};  // 0xFF: start bit, then ones
    EXPECT_EQ(f.rec.txd, want);
    const std::vector<std::pair<Cycle, std::uint8_t>> flags{
        {150, 0x00}, {372, 0x20}, {400, 0x00}, {3092, 0x20}, {3092 + 2720, 0x60}};
    EXPECT_EQ(f.rec.flag_changes, flags);
    EXPECT_EQ(f.u.stats().tx_frames, 2);
    EXPECT_EQ(f.u.stats().tx_ignored_writes, 1);
    f.u.write_ucsra(20'000, 0x40);  // TXC0 is cleared by writing a one to it
    EXPECT_EQ(f.u.ucsra() & 0x40, 0);
    ASSERT_EQ(f.u.tx_log().size(), 2U);
    EXPECT_EQ(f.u.tx_log()[1].write_cycle, 400);
    EXPECT_EQ(f.u.tx_log()[1].start_cycle, 3092);
    EXPECT_EQ(f.u.tx_log()[1].end_cycle, 5812);
}

// §20.11.5: writing UBRR0L restarts the baud rate prescaler at once, also while a byte waits in the transmit buffer
// for the idle shift register: UDR0 written at 150 would load at the tick 100 + 272; UBRR0L written again (the same
// 16) at 300 moves the next tick, and the start bit, to 300 + 16 x (16 + 1) = 572.
TEST(AvrUsartUnit, UbrrlWriteRestartsTheBitClockOfAWaitingByte) {
    Fixture f;
    f.setup_58823(100);
    f.u.write_udr(150, 0x00);
    f.u.write_ubrrl(300, 16);
    f.u.advance_to(20'000);
    ASSERT_FALSE(f.rec.txd.empty());
    EXPECT_EQ(f.rec.txd.front(), (std::pair<Cycle, bool>{300 + 16 * (16 + 1), false}));
}

// Without the logs (a long job's run), the line, the flags and the counts are those of a unit that keeps them:
// TransmitterTimingAndFlags' bytes, and one received byte.
TEST(AvrUsartUnit, WithoutTheLogsTheLineAndTheCountsAreTheSame) {
    Fixture logged;
    Fixture bare(false);
    for (Fixture* f : {&logged, &bare}) {
        f->setup_58823(100);
        f->u.write_udr(150, 0x00);
        f->u.write_udr(400, 0xFF);
        f->u.advance_to(20'000);
        f->u.receive(20'000, 22'584, frame(0x41));  // the stop bit's middle: 9.5 bits of 272 cycles on
    }
    EXPECT_EQ(bare.rec.txd, logged.rec.txd);
    EXPECT_EQ(bare.rec.flag_changes, logged.rec.flag_changes);
    EXPECT_EQ(bare.u.stats().tx_frames, 2);
    EXPECT_EQ(bare.u.stats().rx_frames, 1);
    EXPECT_EQ(bare.u.read_udr(22'584), 0x41);
    EXPECT_EQ(logged.u.tx_log().size(), 2U);
    EXPECT_EQ(logged.u.rx_log().size(), 1U);
    EXPECT_TRUE(bare.u.tx_log().empty());
    EXPECT_TRUE(bare.u.rx_log().empty());
}

TEST(AvrUsartUnit, WritesWithTheTransmitterOffAreIgnored) {
    Fixture f;
    f.u.write_ubrrl(0, 16);
    f.u.write_udr(10, 0x41);
    EXPECT_EQ(f.u.stats().tx_ignored_writes, 1);
    EXPECT_FALSE(f.u.next_event().has_value());
    EXPECT_TRUE(f.u.txd());
}

TEST(AvrUsartUnit, ReceiveBufferHoldsTwoBytesWithTheirErrorFlags) {
    Fixture f;
    f.setup_58823(0);
    f.u.receive(1000, 3584, frame(0x31));
    f.u.receive(4000, 6584, frame(0x32, RxStatus::FramingError));
    f.u.receive(7000, 9584, frame(0x33));  // buffer full: lost, DOR0 on the last byte (§20.7.4)
    EXPECT_EQ(f.u.stats().rx_frames, 2);
    EXPECT_EQ(f.u.stats().rx_overruns, 1);
    EXPECT_EQ(f.u.stats().rx_framing_errors, 1);
    EXPECT_EQ(f.u.ucsra() & 0x9C, 0x80);  // RXC0, no FE0/DOR0/UPE0 for the first byte
    EXPECT_EQ(f.u.read_udr(10'000), 0x31);
    EXPECT_EQ(f.u.ucsra() & 0x9C, 0x80 | 0x10 | 0x08);  // FE0 and DOR0 belong to the second byte
    EXPECT_EQ(f.u.read_udr(10'001), 0x32);
    EXPECT_EQ(f.u.ucsra() & 0x80, 0);
    ASSERT_EQ(f.u.rx_log().size(), 3U);
    EXPECT_FALSE(f.u.rx_log()[2].stored);
}

TEST(AvrUsartUnit, FramesStartingWhileTheReceiverIsOffAreLost) {
    Fixture f;
    f.u.write_ubrrl(0, 16);
    f.u.receive(100, 2684, frame(0x41));
    f.u.write_ucsrb(3000, 0x10);           // RXEN0
    f.u.receive(2900, 5484, frame(0x42));  // started before RXEN0
    f.u.receive(6000, 8584, frame(0x43));
    EXPECT_EQ(f.u.stats().rx_lost_disabled, 2);
    EXPECT_EQ(f.u.stats().rx_frames, 1);
    f.u.write_ucsrb(9000, 0x00);  // disabling the receiver flushes the buffer (§20.7.5)
    EXPECT_EQ(f.u.ucsra() & 0x80, 0);
}
