// The ATmega16 timer modes of the seed 002 firmware (§2.5.3). Marker PB0 rises at cycle M, then one `out` per cycle:
// SFIOR = PSR2 | PSR10 (both prescalers restart at M + 1), TCCR2 (M + 2), TCCR0 (M + 3), TCCR1B (M + 4).
//   * Timer2 CTC, OCR2 = 3, clk/32 (the seed's tuning timer TCCR2 = 0b00001011, plus COM20 to toggle OC2 = PD7).
//   * Timer0 CTC, OCR0 = 2, clk/1024 (the seed's PID tick TCCR0 = 0b00001101, plus COM00 to toggle OC0 = PB3).
//   * Timer1 mode 14 (fast PWM, TOP = ICR1 = 1023), clk/1 (the seed's TCCR1B = 0b00011001), COM1A = 10 on OC1A
//     = PD5 with OCR1A = 300.
#include <stdint.h>

#include "fw_test.h"

int main(void) {
    DDRB = (1 << PB0) | (1 << PB3);
    DDRD = (1 << PD5) | (1 << PD7);
    ICR1 = 1023;
    OCR1A = 300;
    TCCR1A = (1 << COM1A1) | (1 << WGM11);
    OCR2 = 3;
    OCR0 = 2;
    __asm__ volatile("out %[portb], %[mark]\n\t"
                     "out %[sfior], %[psr]\n\t"
                     "out %[tccr2], %[t2]\n\t"
                     "out %[tccr0], %[t0]\n\t"
                     "out %[tccr1b], %[t1]\n\t"
                     :
                     : [portb] "I"(_SFR_IO_ADDR(PORTB)), [mark] "r"((uint8_t)(1 << PB0)),
                       [sfior] "I"(_SFR_IO_ADDR(SFIOR)), [psr] "r"((uint8_t)((1 << PSR2) | (1 << PSR10))),
                       [tccr2] "I"(_SFR_IO_ADDR(TCCR2)),
                       [t2] "r"((uint8_t)((1 << WGM21) | (1 << COM20) | (1 << CS21) | (1 << CS20))),
                       [tccr0] "I"(_SFR_IO_ADDR(TCCR0)),
                       [t0] "r"((uint8_t)((1 << WGM01) | (1 << COM00) | (1 << CS02) | (1 << CS00))),
                       [tccr1b] "I"(_SFR_IO_ADDR(TCCR1B)),
                       [t1] "r"((uint8_t)((1 << WGM13) | (1 << WGM12) | (1 << CS10))));
    for (;;) {
    }
}
