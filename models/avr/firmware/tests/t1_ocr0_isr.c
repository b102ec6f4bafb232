// grbl's stepper start (gnea/grbl v1.1h, stepper.c): Timer1 in CTC mode 4 with OCR1A = 0 (its power-on value)
// and no prescaling, compare A interrupt enabled. On silicon the counter matches 0 at every tick, OCF1A is set
// at the first tick and the ISR runs; stock libsimavr 1.6 registers no timer (prescaler * (OCR + 1) = 1) and
// the ISR never runs. The ISR toggles PB5 (dir_y) and sets OCR1A = 999: from then on a match every 1000 cycles.
// Marker PB0 rises at M; the clock is selected at M + 1. The main loop sleeps (constant interrupt latency).
#include <stdint.h>

#include "fw_test.h"

ISR(TIMER1_COMPA_vect) {
    PINB = MARK_B;
    OCR1A = 999;
}

int main(void) {
    DDRB = MARK_A | MARK_B;
    TCCR1A = 0;
    TIMSK1 = (1 << OCIE1A);
    sei();
    __asm__ volatile("out %[portb], %[mark]\n\t"
                     "sts %[tccr1b], %[cs]\n\t"
                     :
                     : [portb] "I"(_SFR_IO_ADDR(PORTB)), [mark] "r"((uint8_t)MARK_A),
                       [tccr1b] "n"(_SFR_MEM_ADDR(TCCR1B)), [cs] "r"((uint8_t)((1 << WGM12) | (1 << CS10))));
    set_sleep_mode(SLEEP_MODE_IDLE);
    sleep_enable();
    for (;;) sleep_cpu();
}
