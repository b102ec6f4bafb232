// Two silicon details libsimavr 1.6 gets wrong, checked on the pins:
//  1. `sbi PINB, 5` toggles only PB5 (datasheet §14.2.2; simavr writes the read-modify-written PINB and so also
//     toggles PB0, which reads 1 here). PB0 rises at M, PB5 toggles at M + 1 and M + 3 (two sbi, 2 cycles each).
//  2. An interrupt enabled while its flag is already set runs at once: Timer2 CTC (OCR2A = 9, N = 1) sets OCF2A
//     while TIMSK2 = 0; after PB4 rises, TIMSK2 = OCIE2A and the ISR (toggling PB4 again) must follow at once
//     (simavr 1.6 only queues an interrupt raised while enabled: it would wait for the next match).
#include <stdint.h>

#include "fw_test.h"

ISR(TIMER2_COMPA_vect) {
    PINB = MARK_C;
    TIMSK2 = 0;
}

int main(void) {
    DDRB = MARK_A | MARK_B | MARK_C;
    PORTB = MARK_A;
    __asm__ volatile("sbi %[pinb], %[b]\n\t"
                     "sbi %[pinb], %[b]\n\t"
                     :
                     : [pinb] "I"(_SFR_IO_ADDR(PINB)), [b] "I"(PB5));
    OCR2A = 9;
    TCCR2A = (1 << WGM21);
    TCCR2B = (1 << CS20);
    while (!(TIFR2 & (1 << OCF2A))) {
    }
    TCCR2B = 0;  // no further matches: only the flag already set can start the ISR
    sei();
    PORTB = MARK_A | MARK_C;
    TIMSK2 = (1 << OCIE2A);
    for (volatile uint8_t i = 0; i < 50; ++i) {
    }
    fw_end();
}
