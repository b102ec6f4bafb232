// ATmega16 INT0 (PD2) and INT1 (PD3) on falling edges (MCUCR = 0b00001010, GICR = 0b11000000: the seed 002
// firmware's setting, §2.5.3). The naked ISRs set PB0 (INT0) and PB5 (INT1) first thing; main runs NOPs.
#include "fw_test.h"

ISR(INT0_vect, ISR_NAKED) {
    __asm__ volatile("sbi %[portb], 0\n\treti\n\t" : : [portb] "I"(_SFR_IO_ADDR(PORTB)));
}

ISR(INT1_vect, ISR_NAKED) {
    __asm__ volatile("sbi %[portb], 5\n\treti\n\t" : : [portb] "I"(_SFR_IO_ADDR(PORTB)));
}

int main(void) {
    DDRB = (1 << PB0) | (1 << PB5);
    MCUCR = (1 << ISC11) | (1 << ISC01);
    GICR = (1 << INT1) | (1 << INT0);
    sei();
    for (;;) {
        __asm__ volatile(".rept 1000\n\tnop\n\t.endr\n\t");
    }
}
