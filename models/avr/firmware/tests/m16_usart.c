// The ATmega16's USART registers (doc2466 "USART"): UBRRH and UCSRC share I/O address 0x20 ("Accessing UBRRH/UCSRC
// Registers"): URSEL = 1 writes UCSRC, URSEL = 0 UBRRH; a read returns UBRRH, or UCSRC when the location was read in
// the cycle before. The firmware reads the location once, then twice back to back, at reset and after UBRRH = 1 and
// UCSRC = URSEL | USBS | UCSZ1:0 (8N2), then sends the six values at UBRR = 8 (144 cycles a bit, 11 bits a frame).
// Then it answers each byte it receives with the byte + 1 from the RXC interrupt, and its naked TXC interrupt sets
// PB0 (dir_x in the default pin map) first thing.
#include "fw_test.h"

ISR(USART_RXC_vect) {
    UDR = (uint8_t)(UDR + 1);
}

ISR(USART_TXC_vect, ISR_NAKED) {
    __asm__ volatile("sbi %[portb], 0\n\t"
                     "reti\n\t"
                     :
                     : [portb] "I"(_SFR_IO_ADDR(PORTB)));
}

// One read of 0x20, a cycle's pause, then two reads in consecutive cycles.
static void read_shared(uint8_t* out) {
    __asm__ volatile("in %0, %3\n\t"
                     "nop\n\t"
                     "in %1, %3\n\t"
                     "in %2, %3\n\t"
                     : "=&r"(out[0]), "=&r"(out[1]), "=&r"(out[2])
                     : "I"(_SFR_IO_ADDR(UBRRH)));
}

static void send(uint8_t byte) {
    while (!(UCSRA & (1 << UDRE))) {
    }
    UDR = byte;
}

int main(void) {
    uint8_t seen[6];
    DDRB = (1 << PB0);
    read_shared(&seen[0]);
    UBRRH = 1;
    UCSRC = (1 << URSEL) | (1 << USBS) | (1 << UCSZ1) | (1 << UCSZ0);
    read_shared(&seen[3]);
    UBRRH = 0;
    UBRRL = 8;
    UCSRB = (1 << RXEN) | (1 << TXEN);
    for (uint8_t i = 0; i < 6; ++i) send(seen[i]);
    while (!(UCSRA & (1 << TXC))) {
    }
    UCSRA = (1 << TXC);  // cleared by writing a one
    UCSRB |= (1 << RXCIE) | (1 << TXCIE);
    sei();
    for (;;) {
        __asm__ volatile(".rept 1000\n\tnop\n\t.endr\n\t");
    }
}
