#include "axes.h"

#include <avr/interrupt.h>
#include <avr/io.h>

#include "pins.h"

/* Timer0 and Timer2 in CTC mode (WGM = 010), OCnA toggled on compare match (COMnA = 01): TCCRnA = 0x42. */
#define T0_CTC_TOGGLE (_BV(COM0A0) | _BV(WGM01))
#define T0_CTC_CLEAR (_BV(COM0A1) | _BV(WGM01))
#define T2_CTC_TOGGLE (_BV(COM2A0) | _BV(WGM21))
#define T2_CTC_CLEAR (_BV(COM2A1) | _BV(WGM21))

static volatile uint16_t s_count_x;     /* seed: STEPH:STEPL */
static volatile uint8_t s_half_pulse;   /* seed: COUNTER, set by the first match of a STEP period */
static volatile uint8_t s_x_running;

/* seed 003 App. A2 OCR0A_Overflow: 1st match = half a STEP period, 2nd match = one microstep; at zero the
 * ISR disables driver X and its own interrupt. Unlike the listing, the compiler saves SREG and the registers it
 * uses (the listing saves neither SREG nor TEMP), and the flag is cleared on every step. */
ISR(TIMER0_COMPA_vect) {
    if (!s_half_pulse) {
        s_half_pulse = 1;
        return;
    }
    s_half_pulse = 0;
    if (--s_count_x != 0) return;
    PORTB |= _BV(LASER_ENGRAVER_PB_EN_X);
    TIMSK0 = 0;
    s_x_running = 0;
}

void axes_init(void) {
    PORTB = LASER_ENGRAVER_PORTB_INPUTS | PORTB_EN_BOTH;  /* drivers disabled before the pins become outputs */
    DDRB = PORTB_OUTPUTS;
    PORTD &= ~_BV(PIN_STEP_X);
    DDRD |= _BV(PIN_STEP_X);
    TCCR0A = T0_CTC_TOGGLE;
    TCCR2A = T2_CTC_TOGGLE;
}

void axes_prepare(uint8_t ocr_x, uint8_t ocr_y) {
    GTCCR = _BV(TSM) | _BV(PSRASY) | _BV(PSRSYNC); /* hold both prescalers: the two timers start together */
    TCCR0B = 0;
    TCCR2B = 0;
    /* Both compare outputs low: clear-on-match mode and a forced compare (FOC), then toggle again. */
    TCCR0A = T0_CTC_CLEAR;
    TCCR2A = T2_CTC_CLEAR;
    TCCR0B = _BV(FOC0A);
    TCCR2B = _BV(FOC2A);
    TCCR0A = T0_CTC_TOGGLE;
    TCCR2A = T2_CTC_TOGGLE;
    TCNT0 = 0;
    TCNT2 = 0;
    OCR0A = ocr_x;
    OCR2A = ocr_y;
    TIFR0 = _BV(OCF0A);
    TIFR2 = _BV(OCF2A);
    s_half_pulse = 0;
}

void axes_arm_x_interrupt(uint16_t count_x) {
    s_half_pulse = 0;
    s_count_x = count_x;
    /* A zero count would wrap to 65536 steps in App. A2's SBIW: the axis is done. */
    s_x_running = count_x != 0;
    TIFR0 = _BV(OCF0A);  /* a match flag left from the last chord must not count as this chord's half pulse */
    TIMSK0 = count_x != 0 ? _BV(OCIE0A) : 0;
}

uint8_t axes_x_running(void) { return s_x_running; }

void axes_run_timers(uint8_t t2_cs) {
    TCCR0B = T0_CS_1024;
    TCCR2B = t2_cs;
    GTCCR = 0;
}

void axes_start(uint8_t portb, uint8_t t2_cs) {
    PORTB = portb;  /* PB3 (Y_STP) is OC2A's pin: its PORT bit has no effect while Timer2 owns it */
    axes_run_timers(t2_cs);
}

/* App. A3 Count_Steps: wait for a match (half pulse), clear the flag, wait for the next, count one step. */
void axes_count_x_polling(uint16_t count_x) {
    while (count_x != 0) {
        while (!(TIFR0 & _BV(OCF0A))) {
        }
        TIFR0 = _BV(OCF0A);
        while (!(TIFR0 & _BV(OCF0A))) {
        }
        --count_x;
        TIFR0 = _BV(OCF0A);
    }
}

/* App. A2 Count_Steps2 on OCF2A, then SBI PORTB,PB4 (Y off). */
void axes_count_y_polling(uint16_t count_y) {
    while (count_y != 0) {
        while (!(TIFR2 & _BV(OCF2A))) {
        }
        TIFR2 = _BV(OCF2A);
        while (!(TIFR2 & _BV(OCF2A))) {
        }
        --count_y;
        TIFR2 = _BV(OCF2A);
    }
    PORTB |= _BV(LASER_ENGRAVER_PB_EN_Y);
}

/* App. A4 after the wait loop: MOV STEPL,DXL; OUT OCR0A,V_X; STS OCR2A,V_Y; OUT PORTB,DIR. The timers keep
 * running, so an OCR below the running count makes that timer wrap through 255 first (data sheet §15.7.2). */
void axes_load_chord(uint8_t dxl, uint8_t ocr_x, uint8_t ocr_y, uint8_t portb) {
    const uint8_t moves = (portb & PORTB_EN_BOTH) != PORTB_EN_BOTH;
    axes_arm_x_interrupt(moves ? dxl : 0);
    OCR0A = ocr_x;
    OCR2A = ocr_y;
    PORTB = portb;
}

void axes_finish(void) {
    PORTB |= PORTB_EN_BOTH;
    TCCR0B = 0;
    TCCR2B = 0;
    TIMSK0 = 0;
    s_x_running = 0;
}
