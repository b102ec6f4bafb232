/* STEP generation and step counting of seed 003 §5.2.4 / App. A2-A4: Timer0 toggles OC0A (STEP X) and Timer2
 * toggles OC2A (STEP Y) in CTC mode, one STEP period per two compare matches; an axis stops when its
 * active-low EN bit goes high. */
#pragma once
#include <stdint.h>

/* Timer clock selects (ATmega328P data sheet Tables 15-9, 16-5 and 18-9). */
#define T0_CS_1024 (_BV(CS02) | _BV(CS00))              /* seed 003 App. A3: TCCR0B = 0b101 */
#define T2_CS_1024 (_BV(CS22) | _BV(CS21) | _BV(CS20))  /* Timer2 CS = 111 */
#define T2_CS_256 (_BV(CS22) | _BV(CS21))               /* Timer2 CS = 110: App. A3 as listed ("128") */
#define T1_CS_1 _BV(CS10)                               /* Timer1 CS = 001: N = 1 (seed 003 §5.6) */

/* Y's timer and its speed word: Timer2 and the 8-bit OCR2A, or in the timer1-y build (seed 003 §5.6) Timer1 and
 * the 16-bit OCR1A, received low byte first (protocol.h). */
#ifdef LASER_ENGRAVER_TIMER1_Y
typedef uint16_t ocr_y_t;
#define Y_CS_RUN T1_CS_1
#else
typedef uint8_t ocr_y_t;
#define Y_CS_RUN T2_CS_1024
#endif

void axes_init(void);
/* Timers stopped and cleared, both STEP pins low, compare flags clear, OCRs loaded: every command starts from
 * the same state. */
void axes_prepare(uint8_t ocr_x, ocr_y_t ocr_y);
/* Counts X in the Timer0 COMPA interrupt (G00, arcs). */
void axes_arm_x_interrupt(uint16_t count_x);
uint8_t axes_x_running(void);
/* Writes the start byte (the motion starts: seed 003 §5.4 "OUT PORTB") and starts both timers. */
void axes_start(uint8_t portb, uint8_t y_cs);
/* Starts both timers (Timer0 at /1024, Y's at y_cs). */
void axes_run_timers(uint8_t y_cs);
/* G01: counts X by polling OCF0A (App. A3 Count_Steps). */
void axes_count_x_polling(uint16_t count_x);
/* G00: counts Y by polling OCF2A (App. A2 Count_Steps2; OCF1A in the timer1-y build), then disables Y. */
void axes_count_y_polling(uint16_t count_y);
/* Arcs: the next chord replaces the running one without stopping the timers (App. A4). Interrupts must be off. */
void axes_load_chord(uint8_t dxl, uint8_t ocr_x, ocr_y_t ocr_y, uint8_t portb);
/* Both drivers disabled, timers stopped, X interrupt off. */
void axes_finish(void);
