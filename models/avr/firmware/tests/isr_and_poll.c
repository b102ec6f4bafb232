// An interrupt that changes bytes the main loop does not read, as grbl's stepper interrupt does: Timer1 in CTC mode
// at clk/1 with OCR1A = 999 interrupts every 1000 cycles; the ISR counts its calls (a count the main loop never
// reads) and at every 8th sets the flag the main loop polls. The loop is long, as grbl's main loop is (it sums a
// table of 32 bytes, some 300 cycles, and finds the flag too), clears the flag and toggles PB1 (head): toggles
// 8000 cycles apart, each within a turn of the loop. The fast-forward tests run it with and without skipping.
#include "fw_test.h"

static volatile uint32_t calls;
static volatile uint8_t due;
static volatile uint8_t table[32];

ISR(TIMER1_COMPA_vect) {
    if ((++calls & 7U) == 0) due = 1;
}

int main(void) {
    DDRB = (1 << PB1);
    OCR1A = 999;
    TCCR1B = (1 << WGM12) | (1 << CS10);
    TIMSK1 = (1 << OCIE1A);
    sei();
    for (;;) {
        uint8_t sum = 0;
        for (uint8_t k = 0; k < sizeof table; ++k) sum = (uint8_t)(sum + table[k]);
        if (sum == 0 && due) {
            due = 0;
            PINB = (1 << PB1);
        }
    }
}
