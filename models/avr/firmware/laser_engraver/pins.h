/* Pin assignment of seed 003 §5.2.5 / §5.2.6 (Arduino Uno numbering in brackets). */
#pragma once
#include <avr/io.h>

#include "protocol.h"

/* PORTD */
#define PIN_STEP_X PD6 /* [D6] OC0A: Timer0 CTC toggle */

/* PORTB: the start-byte bits of protocol.h. The timer1-y build (seed 003 §5.6) has STEP_Y on OC1A (PB1) and the
 * head on PB3, the pin of Timer2's OC2A where §5.6 moves the servo; the head here is a laser switched by the
 * start byte's HEADER bit, so Timer2 stays off and PB3 is a plain output. */
#ifdef LASER_ENGRAVER_TIMER1_Y
#define PB_STEP_Y LASER_ENGRAVER_T1Y_PB_STEP_Y
#define PB_HEADER LASER_ENGRAVER_T1Y_PB_HEADER
#else
#define PB_STEP_Y LASER_ENGRAVER_PB_STEP_Y
#define PB_HEADER LASER_ENGRAVER_PB_HEADER
#endif
#define PORTB_EN_BOTH (_BV(LASER_ENGRAVER_PB_EN_X) | _BV(LASER_ENGRAVER_PB_EN_Y))
#define PORTB_OUTPUTS                                                                                        \
    (_BV(LASER_ENGRAVER_PB_DIR_X) | _BV(PB_HEADER) | _BV(LASER_ENGRAVER_PB_EN_X) | _BV(PB_STEP_Y) |          \
     _BV(LASER_ENGRAVER_PB_EN_Y) | _BV(LASER_ENGRAVER_PB_DIR_Y))
