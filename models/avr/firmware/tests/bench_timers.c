// Speed benchmark, timer-heavy firmware: Timer0 and Timer2 toggle STEP_X / STEP_Y in CTC mode at 20 kHz and
// 16 kHz (OCR0A = 49 and OCR2A = 124 at N = 8), their compare ISRs count steps as seed 003's G00 does, and
// Timer1 runs the 10 kHz ISR of bench_idle.c.
#include <stdint.h>

#include "fw_test.h"

volatile uint16_t steps_x;
volatile uint16_t steps_y;

ISR(TIMER0_COMPA_vect) { ++steps_x; }
ISR(TIMER2_COMPA_vect) { ++steps_y; }
ISR(TIMER1_COMPA_vect) { PINB = (1 << PB1); }

int main(void) {
    DDRB = (1 << PB1) | (1 << PB3) | (1 << PB0) | (1 << PB5);
    DDRD = (1 << PD6);
    OCR0A = 49;
    TCCR0A = (1 << COM0A0) | (1 << WGM01);
    TCCR0B = (1 << CS01);
    OCR2A = 124;
    TCCR2A = (1 << COM2A0) | (1 << WGM21);
    TCCR2B = (1 << CS21);
    OCR1A = 1599;
    TCCR1B = (1 << WGM12) | (1 << CS10);
    TIMSK0 = (1 << OCIE0A);
    TIMSK2 = (1 << OCIE2A);
    TIMSK1 = (1 << OCIE1A);
    sei();
    for (;;) {
    }
}
