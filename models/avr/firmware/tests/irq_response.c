// Interrupt response time (datasheet "Interrupt Response Time": at least 4 clock cycles from the flag to the
// vector, then the vector's RJMP, 2 cycles, as avr-ld --relax builds the table). Timer0 CTC at N = 1 toggles
// OC0A (PD6, step_x) at the compare match that sets OCF0A; the naked ISR's first instruction sets PB0 (dir_x).
// The main program runs 1-cycle NOPs, so the CPU takes the interrupt as soon as the flag is set: PB0 rises
// 4 + 2 = 6 cycles after the first OC0A edge. Built with SLEEP_IN_LOOP the main program sleeps (Idle mode, SM = 000:
// the timers run on) instead: waking adds 4 cycles to the response (datasheet "Interrupt Response Time"; Idle's
// start-up time is 0, "Sleep Modes" §9), so PB0 rises 4 + 4 + 2 = 10 cycles after it.
#include "fw_test.h"

ISR(TIMER0_COMPA_vect, ISR_NAKED) {
    __asm__ volatile("sbi %[portb], 0\n\t"
                     "reti\n\t"
                     :
                     : [portb] "I"(_SFR_IO_ADDR(PORTB)));
}

int main(void) {
    DDRB = MARK_A;
    DDRD = (1 << PD6);
    OCR0A = 99;
    TCCR0A = (1 << COM0A0) | (1 << WGM01);
    TIMSK0 = (1 << OCIE0A);
    sei();
#ifdef SLEEP_IN_LOOP
    SMCR = (1 << SE);  // SM = 000: Idle
#endif
    TCCR0B = (1 << CS00);
    for (;;) {
#ifdef SLEEP_IN_LOOP
        sleep_cpu();
#else
        __asm__ volatile(".rept 1000\n\tnop\n\t.endr\n\t");
#endif
    }
}
