// Speed benchmark, idle firmware: Timer1 CTC at 10 kHz (OCR1A = 1599, N = 1), its ISR
// toggles PB1 (head); the main loop spins.
#include "fw_test.h"

ISR(TIMER1_COMPA_vect) { PINB = (1 << PB1); }

int main(void) {
    DDRB = (1 << PB1);
    OCR1A = 1599;
    TCCR1B = (1 << WGM12) | (1 << CS10);
    TIMSK1 = (1 << OCIE1A);
    sei();
    for (;;) {
    }
}
