// Port and interrupt details of the ATmega328P model where libsimavr 1.6 differs from silicon, and a firmware
// that uses the USART interrupts as grbl does.
#include "avr_test_support.hpp"
#include "uart/cp2102.hpp"

using namespace cnc::avr;
using namespace cnc::avr::test;
using cnc::TimePs;

TEST(AvrChip, SbiOnPinxTogglesOnlyTheAddressedPin) {
    // PORTB = PB0 at M, then `sbi PINB, 5` twice (2 cycles each): PB5 toggles at M + 1 and M + 3 and PB0, which
    // reads 1, stays high (stock libsimavr 1.6 writes PINB | 1 << 5 and toggles PB0 too: low at M + 1).
    AvrBench b(config_for(AVR_FW_IRQ_AND_PINS_ELF));
    b.run_until_ps(cnc::kPsPerMs);
    const auto pb0 = edge_cycles(b, "dir_x");
    ASSERT_EQ(pb0.size(), 1U);
    const Cycle m = pb0.front();
    EXPECT_EQ(edge_cycles(b, "dir_y"), (std::vector<Cycle>{m + 1, m + 3}));
}

TEST(AvrChip, InterruptEnabledWhileItsFlagIsSetRunsAtOnce) {
    // OCF2A is set (Timer2 stopped afterwards) before TIMSK2.OCIE2A is written with I = 1: the ISR must run
    // right after the write (interrupt response + ISR prologue), toggling PB4 once. Stock libsimavr 1.6 never
    // runs it (no new match).
    AvrBench b(config_for(AVR_FW_IRQ_AND_PINS_ELF));
    b.run_until_ps(cnc::kPsPerMs);
    const auto pb4 = edge_cycles(b, "en_y");
    ASSERT_EQ(pb4.size(), 2U);
    EXPECT_GT(pb4[1] - pb4[0], 4);
    EXPECT_LT(pb4[1] - pb4[0], 30);
    EXPECT_TRUE(b.avr.stopped());
}

TEST(AvrChip, InterruptDrivenSerialEchoesALineBackToBack) {
    // grbl's serial.c pattern: RX complete ISR, and a UDRE ISR that empties a ring buffer. The line "hello\n" from
    // the CP2102 (57 553.96 Bd) is echoed after its '\n'; the UDRE interrupt (a level interrupt) refills UDR0 as
    // soon as each byte moves to the shift register, so the six frames follow each other exactly 2720 cycles
    // apart (10 bits of 272 cycles).
    AvrBench b(config_with_usart_logs(AVR_FW_USART_IRQ_ECHO_ELF));
    cnc::uart::Cp2102 cp("cp", cnc::uart::Cp2102Config{57'600});
    cp.txd(b.rxd);
    cp.rxd(*b.signals[kTxdLine]);
    const std::string text = "hello\n";
    sc_core::sc_spawn([&] {
        sc_core::wait(at_ps(cnc::kPsPerMs));
        cp.usb_write(std::vector<std::uint8_t>(text.begin(), text.end()));
    });
    b.run_until_ps(6 * cnc::kPsPerMs);

    const auto& tx = b.avr.chip().usart().tx_log();
    ASSERT_EQ(tx.size(), text.size());
    for (std::size_t i = 0; i < tx.size(); ++i) {
        EXPECT_EQ(tx[i].byte, static_cast<std::uint8_t>(text[i]));
        if (i > 0) {
            EXPECT_EQ(tx[i].start_cycle - tx[i - 1].start_cycle, 2720) << i;
        }
    }
    ASSERT_EQ(cp.rx_log().size(), text.size());
    for (std::size_t i = 0; i < text.size(); ++i) EXPECT_EQ(cp.rx_log()[i].byte, static_cast<std::uint8_t>(text[i]));
    EXPECT_EQ(b.avr.stats().usart.rx_frames, 6);
    EXPECT_EQ(b.avr.stats().usart.rx_overruns, 0);
    EXPECT_EQ(b.avr.stats().usart.tx_ignored_writes, 0);
}
