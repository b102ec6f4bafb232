// OCR0A written while Timer0 runs in CTC mode (N = 1, OC0A = PD6 toggles). Datasheet §15.7.2: OCR0A takes
// effect at once; a value below the current count is missed and the counter runs to 0xFF and wraps first.
//   OCR0A = 100, clock selected at M1 + 1 (marker PB0 rises at M1)
//   OCR0A = 200 (above the count) written at M2 + 1 (marker PB5 rises at M2)
//   OCR0A = 10 (below the count) written at M3 + 1 (marker PB4 rises at M3)
#include <stdint.h>

#include "fw_test.h"

static void spin(uint16_t n) {
    for (volatile uint16_t i = 0; i < n; ++i) {
    }
}

#define MARK_AND_WRITE(marks, reg, value)                                                                      \
    __asm__ volatile("out %[portb], %[m]\n\t"                                                                  \
                     "out %[r], %[v]\n\t"                                                                      \
                     :                                                                                         \
                     : [portb] "I"(_SFR_IO_ADDR(PORTB)), [m] "r"((uint8_t)(marks)), [r] "I"(_SFR_IO_ADDR(reg)), \
                       [v] "r"((uint8_t)(value)))

int main(void) {
    DDRB = MARK_A | MARK_B | MARK_C;
    DDRD = (1 << PD6);
    OCR0A = 100;
    TCCR0A = (1 << COM0A0) | (1 << WGM01);
    MARK_AND_WRITE(MARK_A, TCCR0B, 1 << CS00);
    spin(100);
    MARK_AND_WRITE(MARK_A | MARK_B, OCR0A, 200);
    spin(150);
    MARK_AND_WRITE(MARK_A | MARK_B | MARK_C, OCR0A, 10);
    for (;;) {
    }
}
