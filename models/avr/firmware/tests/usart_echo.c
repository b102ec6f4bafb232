// USART0 receiver at UBRR0 = 16, U2X0 = 0 (seed 003 §5.3.1), polled as seed 003's `Receive` routine does.
// UBRR0 is set at once, but the receiver stays off for the first 2 ms (bytes arriving then are lost); then
// RXEN0/TXEN0 are set and the marker PB0 rises. Each byte: PB5 (dir_y) toggles 4..8 cycles after RXC0 is set, FE0 is read, then UDR0; the
// byte is echoed, or 0xFE if it had a framing error.
#include <stdint.h>

#include "fw_test.h"

int main(void) {
    DDRB = MARK_A | MARK_B;
    UBRR0 = 16;
    for (volatile uint16_t i = 0; i < 1700; ++i) {  // about 2 ms at 16 MHz (19 cycles per turn)
    }
    UCSR0B = (1 << RXEN0) | (1 << TXEN0);
    PORTB = MARK_A;
    for (;;) {
        __asm__ volatile("1: lds __tmp_reg__, %[ucsr0a]\n\t"
                         "sbrs __tmp_reg__, %[rxc]\n\t"
                         "rjmp 1b\n\t"
                         "out %[pinb], %[m]\n\t"
                         :
                         : [ucsr0a] "n"(_SFR_MEM_ADDR(UCSR0A)), [rxc] "I"(RXC0), [pinb] "I"(_SFR_IO_ADDR(PINB)),
                           [m] "r"((uint8_t)MARK_B));
        const uint8_t status = UCSR0A;
        const uint8_t byte = UDR0;
        while (!(UCSR0A & (1 << UDRE0))) {
        }
        UDR0 = (status & (1 << FE0)) ? 0xFE : byte;
    }
}
