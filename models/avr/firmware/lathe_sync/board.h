/* Seed 002's board (pin map and constants of the §2.5.3 listing): ATmega16 at 8 MHz. Our C re-implementation of
 * the thesis's firmware (the listing of §2.5.3); choices where the listing is ambiguous are marked "seed option". */
#ifndef LATHE_SYNC_BOARD_H
#define LATHE_SYNC_BOARD_H

#include <avr/io.h>
#include <stdint.h>

#define LS_PPR 780             /* leadscrew pulses/rev: 30 slots x 26 (§2.5.3) */
#define SP_PPR 40              /* spindle pulses/rev (§2.5.3) */
#define LS_PITCH 3175          /* leadscrew pitch, um (§2.5.3) */
#define PWM_TOP 0x03FF         /* Timer1 TOP = ICR1: 10-bit PWM (§2.5.3) */
#define PWM_SLOW 600           /* doMove's approach duty (§2.5.3) */
#define SCALING_FACTOR_BITS 5  /* gains stored x32 (§2.5.3) */
#define MAX_INT INT16_MAX
#define MAX_LONG INT32_MAX
#define MAX_I_TERM (MAX_LONG / 2)

/* PORTD (§2.5.3): PD1:PD0 = DIR2:DIR1 of the L298, PD2 = INT0 motor encoder, PD3 = INT1 spindle encoder,
 * PD5 = OC1A PWM to EN, PD6 = INDEX, PD7 = LIMIT (normally 1). */
#define DIR_MASK 0x03
#define RIGHT 0x01 /* seed: `#define RIGHT 0b01;` (the listing's stray ';' dropped) */
#define LEFT 0x02
#define INDEX_HIGH() ((PIND & (1 << PD6)) != 0)
#define LIMIT_OK() ((PIND & (1 << PD7)) != 0)

static inline uint8_t direction(void) { return PORTD & DIR_MASK; }
static inline void set_direction(uint8_t d) { PORTD = (uint8_t)((PORTD & ~DIR_MASK) | (d & DIR_MASK)); }

#define PID_START() (TCCR0 |= 0x05) /* clk/1024 (§2.5.3) */
#define PID_STOP() (TCCR0 &= 0xFA)
#define PWM_START() (TCCR1A |= 0x80) /* COM1A1: OC1A drives PD5 */
#define PWM_STOP() (TCCR1A &= 0x7F)

/* EEPROM map (§2.5.3): 3 = OCR0, 4 = P, 6 = I, 8 = D (x32), 18 = OCR2 of the tuning run, 20.. = 400 periods. */
#define EE_OCR0 ((uint8_t*)3)
#define EE_P ((uint16_t*)4)
#define EE_I ((uint16_t*)6)
#define EE_D ((uint16_t*)8)
#define EE_OCR2 ((uint8_t*)18)
#define EE_PERIODS ((uint8_t*)20)
#define TUNING_PERIODS 400

#endif
