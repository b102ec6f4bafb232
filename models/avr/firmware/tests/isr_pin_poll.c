// A loop polling a pin that an interrupt drives: Timer1 in CTC mode at clk/1 with OCR1A = 1000 interrupts every
// 1001 cycles (not a multiple of the loop's turn, so the interrupt lands on each of its instructions in turn) and
// toggles PB2 (an output, so PINB reads it back); the main loop follows PB2 onto PB1 (head): head toggles 1001
// cycles apart. The loop's bytes are the same after every interrupt; only PINB, read through its
// handler, tells it the pin changed. The fast-forward tests run it with and without skipping.
#include "fw_test.h"

ISR(TIMER1_COMPA_vect) { PORTB ^= (1 << PB2); }  // through PORTB: PINB's byte in the data space is not written

int main(void) {
    DDRB = (1 << PB1) | (1 << PB2);
    OCR1A = 1000;
    TCCR1B = (1 << WGM12) | (1 << CS10);
    TIMSK1 = (1 << OCIE1A);
    sei();
    uint8_t seen = 0;
    for (;;) {
        const uint8_t now = PINB & (1 << PB2);
        if (now != seen) {
            seen = now;
            PINB = (1 << PB1);
        }
    }
}
