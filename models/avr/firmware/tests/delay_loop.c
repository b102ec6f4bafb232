// A busy delay (avr-libc's _delay_loop_2: SBIW and BRNE, 4 cycles a turn, as _delay_ms and grbl's delay_ms wait) with
// interrupts meeting it: the main loop waits 15,000 turns at a time; Timer1 in CTC mode at clk/1 with OCR1A = 1232
// interrupts every 1233 cycles (landing on both of the loop's instructions, so a toggle 2 to 4 cycles after the
// match) and toggles PB1 (head). The fast-forward tests run it with and without skipping.
#include "fw_test.h"

#include <util/delay_basic.h>

ISR(TIMER1_COMPA_vect) { PINB = (1 << PB1); }

int main(void) {
    DDRB = (1 << PB1);
    OCR1A = 1232;
    TCCR1B = (1 << WGM12) | (1 << CS10);
    TIMSK1 = (1 << OCIE1A);
    sei();
    for (;;) _delay_loop_2(15000);
}
