/* Pin assignment of seed 003 §5.2.5 / §5.2.6 (Arduino Uno numbering in brackets). */
#pragma once
#include <avr/io.h>

#include "protocol.h"

/* PORTD */
#define PIN_STEP_X PD6 /* [D6] OC0A: Timer0 CTC toggle */

/* PORTB: the start-byte bits of protocol.h */
#define PORTB_EN_BOTH (_BV(LASER_ENGRAVER_PB_EN_X) | _BV(LASER_ENGRAVER_PB_EN_Y))
#define PORTB_OUTPUTS                                                                                        \
    (_BV(LASER_ENGRAVER_PB_DIR_X) | _BV(LASER_ENGRAVER_PB_HEADER) | _BV(LASER_ENGRAVER_PB_EN_X) |            \
     _BV(LASER_ENGRAVER_PB_STEP_Y) | _BV(LASER_ENGRAVER_PB_EN_Y) | _BV(LASER_ENGRAVER_PB_DIR_Y))
