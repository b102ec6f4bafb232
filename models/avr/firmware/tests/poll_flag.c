// A polling loop, as seed 003's firmware waits for its timers: Timer1 in CTC mode at clk/1 with OCR1A = 999 sets
// OCF1A every 1000 cycles; the main loop spins on the flag (no interrupt), clears it and toggles PB1 (head), so the
// toggles must come exactly 1000 cycles apart. The fast-forward tests run it with and without skipping.
#include "fw_test.h"

int main(void) {
    DDRB = (1 << PB1);
    OCR1A = 999;
    TCCR1B = (1 << WGM12) | (1 << CS10);
    for (;;) {
        while (!(TIFR1 & (1 << OCF1A))) {
        }
        TIFR1 = (1 << OCF1A);
        PINB = (1 << PB1);
    }
}
