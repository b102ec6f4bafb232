// USART0 transmitter at UBRR0 = 16, U2X0 = 0 (seed 003 §5.3.1: 58 823.5 Bd, 272 cycles per bit), 8N1.
//   UBRR0L written at M1 + 1 (marker PB0 rises at M1): the baud rate generator restarts there.
//   UDR0 = 0x55 written at M2 + 1 (marker PB5 rises at M2).
//   Then, polling UCSR0A (lds 2 + sbrs 1 + rjmp 2 = 5 cycles per turn), PB4 (en_y) toggles 4..8 cycles after
//   UDRE0 is set, and 0xA3 and 0x0F are written right after it; finally PB4 toggles 4..8 cycles after TXC0.
#include <stdint.h>

#include "fw_test.h"

#define WAIT_FLAG_AND_TOGGLE(bit)                                                                            \
    __asm__ volatile("1: lds __tmp_reg__, %[ucsr0a]\n\t"                                                     \
                     "sbrs __tmp_reg__, %[b]\n\t"                                                            \
                     "rjmp 1b\n\t"                                                                           \
                     "out %[pinb], %[m]\n\t"                                                                 \
                     :                                                                                       \
                     : [ucsr0a] "n"(_SFR_MEM_ADDR(UCSR0A)), [b] "I"(bit), [pinb] "I"(_SFR_IO_ADDR(PINB)), \
                       [m] "r"((uint8_t)MARK_C))

int main(void) {
    DDRB = MARK_A | MARK_B | MARK_C;
    UCSR0B = (1 << TXEN0);
    __asm__ volatile("out %[portb], %[m]\n\t"
                     "sts %[ubrr], %[v]\n\t"
                     :
                     : [portb] "I"(_SFR_IO_ADDR(PORTB)), [m] "r"((uint8_t)MARK_A), [ubrr] "n"(_SFR_MEM_ADDR(UBRR0L)),
                       [v] "r"((uint8_t)16));
    for (volatile uint8_t i = 0; i < 40; ++i) {
    }
    __asm__ volatile("out %[portb], %[m]\n\t"
                     "sts %[udr], %[v]\n\t"
                     :
                     : [portb] "I"(_SFR_IO_ADDR(PORTB)), [m] "r"((uint8_t)(MARK_A | MARK_B)),
                       [udr] "n"(_SFR_MEM_ADDR(UDR0)), [v] "r"((uint8_t)0x55));
    WAIT_FLAG_AND_TOGGLE(UDRE0);
    UDR0 = 0xA3;
    WAIT_FLAG_AND_TOGGLE(UDRE0);
    UDR0 = 0x0F;
    WAIT_FLAG_AND_TOGGLE(TXC0);
    fw_end();
}
