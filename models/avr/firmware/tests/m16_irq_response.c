// ATmega16 interrupt response time: Timer0 CTC at N = 1 toggles OC0 (PB3, step_y in the default pin map) at the
// compare match that sets OCF0; the naked ISR's first instruction sets PB0 (dir_x). Main runs 1-cycle NOPs, so
// PB0 rises 4 (response) + 2 (the vector's RJMP, avr-ld --relax) = 6 cycles after the first OC0 edge (datasheet
// doc2466 "Interrupt Response Time").
#include "fw_test.h"

ISR(TIMER0_COMP_vect, ISR_NAKED) {
    __asm__ volatile("sbi %[portb], 0\n\t"
                     "reti\n\t"
                     :
                     : [portb] "I"(_SFR_IO_ADDR(PORTB)));
}

int main(void) {
    DDRB = (1 << PB0) | (1 << PB3);
    OCR0 = 99;
    TIMSK = (1 << OCIE0);
    sei();
    TCCR0 = (1 << WGM01) | (1 << COM00) | (1 << CS00);  // CTC, toggle OC0, clk/1
    for (;;) {
        __asm__ volatile(".rept 1000\n\tnop\n\t.endr\n\t");
    }
}
