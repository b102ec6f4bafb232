// The ATmega16's USART on the AVR model (the grbl board's clock, 16 MHz), against datasheet doc2466 "USART":
// UBRRH and UCSRC at one I/O address (URSEL selects the write; a read is UBRRH unless the location was read the
// cycle before), the frame format UCSRC sets, and the RXC (11) and TXC (13) vectors of Table 18. The firmware is
// models/avr/firmware/tests/m16_usart.c.
#include <gtest/gtest.h>

#include <vector>

#include "avr_test_support.hpp"
#include "uart/core/uart_frame.hpp"

using namespace cnc::avr;
using namespace cnc::avr::test;

namespace {

// UBRR = 8: 16 (UBRR + 1) = 144 cycles a bit; 8N2 = 1 start + 8 data + 2 stop bits.
constexpr Cycle kBitCycles = 144;
constexpr Cycle kFrameCycles = 11 * kBitCycles;

AvrCoreConfig m16_usart() {
    AvrCoreConfig cfg = config_with_usart_logs(AVR_FW_M16_USART_ELF);
    cfg.mcu = "atmega16";
    return cfg;
}

}  // namespace

TEST(Atmega16Usart, SharedAddressFramesAndVectors) {
    AvrBench b(m16_usart());
    // 'A' at the AVR's own bit rate, at 2 ms: the six frames are out by then.
    const cnc::TimePs t0 = 2 * cnc::kPsPerMs;
    sc_core::sc_spawn([&b, t0] {
        for (const cnc::Edge& e : cnc::uart::frame_edges('A', t0, cnc::uart::BitClock{kBitCycles, 16'000'000})) {
            sc_core::wait(at_ps(e.t_ps - now_ps()));
            b.rxd.write(e.level);
        }
    });
    b.run_until_ps(4 * cnc::kPsPerMs);

    // Reset: UBRRH 0 (once, and first of the pair), UCSRC 0x86 (URSEL reads one, UCSZ1:0 = 11: 8N1). After UBRRH = 1
    // and UCSRC = URSEL | USBS | UCSZ1 | UCSZ0: 1, 1, 0x8E. Then the answer to 'A': 'B'.
    const std::vector<std::uint8_t> want{0x00, 0x00, 0x86, 0x01, 0x01, 0x8E, 'B'};
    const auto& tx = b.avr.chip().usart().tx_log();
    ASSERT_EQ(tx.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(tx[i].byte, want[i]) << i;
    // The polled bytes follow each other with no gap, each 11 bit times at UBRR = 8 (a UCSRC write taken as UBRRH's
    // would have made UBRR 0xE08).
    for (std::size_t i = 1; i < 6; ++i) EXPECT_EQ(tx[i].start_cycle - tx[i - 1].start_cycle, kFrameCycles) << i;
    EXPECT_EQ(tx[5].end_cycle - tx[5].start_cycle, kFrameCycles);

    const auto& rx = b.avr.chip().usart().rx_log();
    ASSERT_EQ(rx.size(), 1U);
    EXPECT_EQ(rx[0].byte, 'A');
    EXPECT_TRUE(rx[0].stored);
    EXPECT_EQ(rx[0].status, cnc::uart::RxStatus::Ok);
    // The RXC vector answered (tx[6]); TXC is set when that frame's last stop bit ends, and its naked vector's sbi
    // comes 4 (response) + 2 (the vector's RJMP) cycles later, the main loop running 1-cycle NOPs.
    EXPECT_GT(tx[6].write_cycle, rx[0].decision_cycle);
    const auto marker = edge_cycles(b, "dir_x");
    ASSERT_EQ(marker.size(), 1U);
    EXPECT_EQ(marker.front(), tx[6].end_cycle + 4 + 2);
}
