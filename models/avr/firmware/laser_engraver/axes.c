#include "axes.h"

#include <avr/interrupt.h>
#include <avr/io.h>

#include "pins.h"

/* Timer0 and Timer2 in CTC mode (WGM = 010), OCnA toggled on compare match (COMnA = 01): TCCRnA = 0x42. */
#define T0_CTC_TOGGLE (_BV(COM0A0) | _BV(WGM01))
#define T0_CTC_CLEAR (_BV(COM0A1) | _BV(WGM01))
#define T2_CTC_TOGGLE (_BV(COM2A0) | _BV(WGM21))
#define T2_CTC_CLEAR (_BV(COM2A1) | _BV(WGM21))

/* Y's timer. Seed: Timer2 as Timer0. Timer1-y build (seed 003 §5.6): Timer1 in CTC mode 4 (WGM13:0 = 0100, TOP =
 * OCR1A: data sheet Table 16-4), OC1A toggled on match (COM1A1:0 = 01, Table 16-1). WGM12 sits in TCCR1B with the
 * clock select, so a stopped Timer1 keeps it; FOC1A is in TCCR1C. OCR1A and TCNT1 are 16-bit registers written
 * through TEMP, high byte first (§16.3): avr-gcc writes a 16-bit I/O register in that order. */
#ifdef LASER_ENGRAVER_TIMER1_Y
#define TY_CTC_TOGGLE _BV(COM1A0)
#define TY_CTC_CLEAR _BV(COM1A1)
#define TY_CTRL_A TCCR1A
#define TY_STOP() (TCCR1B = _BV(WGM12))
#define TY_RUN(cs) (TCCR1B = _BV(WGM12) | (cs))
#define TY_FORCE() (TCCR1C = _BV(FOC1A))
#define TY_TCNT TCNT1
#define TY_OCR OCR1A
#define TY_TIFR TIFR1
#define TY_OCF OCF1A
#else
#define TY_CTC_TOGGLE T2_CTC_TOGGLE
#define TY_CTC_CLEAR T2_CTC_CLEAR
#define TY_CTRL_A TCCR2A
#define TY_STOP() (TCCR2B = 0)
#define TY_RUN(cs) (TCCR2B = (cs))
#define TY_FORCE() (TCCR2B = _BV(FOC2A))
#define TY_TCNT TCNT2
#define TY_OCR OCR2A
#define TY_TIFR TIFR2
#define TY_OCF OCF2A
#endif

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
    TY_CTRL_A = TY_CTC_TOGGLE;
}

void axes_prepare(uint8_t ocr_x, ocr_y_t ocr_y) {
    GTCCR = _BV(TSM) | _BV(PSRASY) | _BV(PSRSYNC); /* hold both prescalers: the two timers start together */
    TCCR0B = 0;
    TY_STOP();
    /* Both compare outputs low: clear-on-match mode and a forced compare (FOC), then toggle again. */
    TCCR0A = T0_CTC_CLEAR;
    TY_CTRL_A = TY_CTC_CLEAR;
    TCCR0B = _BV(FOC0A);
    TY_FORCE();
    TCCR0A = T0_CTC_TOGGLE;
    TY_CTRL_A = TY_CTC_TOGGLE;
    TCNT0 = 0;
    TY_TCNT = 0;
    OCR0A = ocr_x;
    TY_OCR = ocr_y;
    TIFR0 = _BV(OCF0A);
    TY_TIFR = _BV(TY_OCF);
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

void axes_run_timers(uint8_t y_cs) {
    TCCR0B = T0_CS_1024;
    TY_RUN(y_cs);
    GTCCR = 0;
}

void axes_start(uint8_t portb, uint8_t y_cs) {
    PORTB = portb;  /* Y_STP's PORT bit has no effect while Y's timer owns the pin (OC2A, or OC1A) */
    axes_run_timers(y_cs);
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

/* App. A2 Count_Steps2 on OCF2A (OCF1A), then SBI PORTB,PB4 (Y off). */
void axes_count_y_polling(uint16_t count_y) {
    while (count_y != 0) {
        while (!(TY_TIFR & _BV(TY_OCF))) {
        }
        TY_TIFR = _BV(TY_OCF);
        while (!(TY_TIFR & _BV(TY_OCF))) {
        }
        --count_y;
        TY_TIFR = _BV(TY_OCF);
    }
    PORTB |= _BV(LASER_ENGRAVER_PB_EN_Y);
}

/* App. A4 after the wait loop: MOV STEPL,DXL; OUT OCR0A,V_X; STS OCR2A,V_Y; OUT PORTB,DIR. The timers keep
 * running, so an OCR below the running count makes that timer wrap through 255 first (data sheet §15.7.2). */
void axes_load_chord(uint8_t dxl, uint8_t ocr_x, ocr_y_t ocr_y, uint8_t portb) {
    const uint8_t moves = (portb & PORTB_EN_BOTH) != PORTB_EN_BOTH;
    axes_arm_x_interrupt(moves ? dxl : 0);
    OCR0A = ocr_x;
    TY_OCR = ocr_y;
    PORTB = portb;
}

void axes_finish(void) {
    PORTB |= PORTB_EN_BOTH;
    TCCR0B = 0;
    TY_STOP();
    TIMSK0 = 0;
    s_x_running = 0;
}
