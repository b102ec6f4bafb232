// CTC mode with the compare output toggling OCnA (Timer0: OC0A = PD6 = step_x; Timer2: OC2A = PB3 = step_y).
// Build-time parameters: TIMER (0 or 2), CS (clock select bits), OCR, PRELOAD (TCNT written while stopped, or -1),
// SYNC (1: the prescaler is held with GTCCR.TSM and released at a known cycle; 0: it free-runs from reset and the
// clock is selected at a known cycle).
//   SYNC = 1: marker PB0 rises at cycle M; the prescaler restarted at M - 1 (out GTCCR; out PORTB).
//   SYNC = 0: marker PB0 rises at cycle M; the clock select was written at M + 1 (out PORTB; out/sts TCCRnB).
#include <stdint.h>

#include "fw_test.h"

#if TIMER == 0
#define TCCRA TCCR0A
#define TCCRB TCCR0B
#define TCNT TCNT0
#define OCRA OCR0A
#define CTC_TOGGLE ((1 << COM0A0) | (1 << WGM01))
#define PSR_BIT PSRSYNC
#define SET_CS_ASM "out %[tccrb], %[cs]\n\t"
#define TCCRB_ADDR "I"(_SFR_IO_ADDR(TCCR0B))
#else
#define TCCRA TCCR2A
#define TCCRB TCCR2B
#define TCNT TCNT2
#define OCRA OCR2A
#define CTC_TOGGLE ((1 << COM2A0) | (1 << WGM21))
#define PSR_BIT PSRASY
#define SET_CS_ASM "sts %[tccrb], %[cs]\n\t"
#define TCCRB_ADDR "n"(_SFR_MEM_ADDR(TCCR2B))
#endif

int main(void) {
    DDRB = MARK_A | MARK_B | (1 << PB3);
    DDRD = (1 << PD6);
    OCRA = OCR;
    TCCRA = CTC_TOGGLE;
#if PRELOAD >= 0
    TCNT = PRELOAD;
#endif
#if SYNC
    GTCCR = (1 << TSM) | (1 << PSR_BIT);
    TCCRB = CS;
    __asm__ volatile("out %[gtccr], __zero_reg__\n\t"
                     "out %[portb], %[mark]\n\t"
                     :
                     : [gtccr] "I"(_SFR_IO_ADDR(GTCCR)), [portb] "I"(_SFR_IO_ADDR(PORTB)), [mark] "r"((uint8_t)MARK_A));
#else
    __asm__ volatile("out %[portb], %[mark]\n\t" SET_CS_ASM
                     :
                     : [portb] "I"(_SFR_IO_ADDR(PORTB)), [mark] "r"((uint8_t)MARK_A), [tccrb] TCCRB_ADDR,
                       [cs] "r"((uint8_t)CS));
#endif
    for (;;) {
    }
}
