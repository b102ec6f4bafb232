#include "motion.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <util/delay.h>

#include "board.h"
#include "control.h"
#include "keypad.h"
#include "lcd.h"

int32_t slip;
int32_t length_pulses;

static int32_t total(void) {
    cli();
    const int32_t t = total_ls_pulses;
    sei();
    return t;
}

void doBrake(void) {
    const uint8_t was_left = direction() == LEFT;
    set_direction(was_left ? 0x00 : 0x03); /* alternates the shorting transistor pair (§2.5.3) */
    PORTD |= 1 << PD5;                     /* EN high with DIR1 == DIR2: brake */
    _delay_ms(500);
    PORTD &= (uint8_t)~(1 << PD5);
    set_direction(was_left ? LEFT : RIGHT);
}

void doCut(void) {
    cli();
    total_ls_pulses = 0;
    ls_pulses = 0;
    sei();
    OCR1A = 0;
    pid_reset();
    lcd_show_p(PSTR("waiting for sp"), NULL);
    while (!INDEX_HIGH()) {
    }
    while (INDEX_HIGH()) {
    }
    /* Left exactly on the INDEX falling edge: the same spindle angle every pass. */
    cli();
    Error = (int16_t)slip;
    sei();
    PID_START();
    PWM_START();
    while (!PRESSED_D && LIMIT_OK() && (total() < length_pulses + slip || length_pulses == -1)) {
    }
    PID_STOP();
    PWM_STOP();
    doBrake();
    const int32_t t = total();
    if (length_pulses == -1 || t < length_pulses + slip) {
        length_pulses = t - slip;
        slip = 0;
    } else {
        slip = t - (length_pulses + slip); /* the overshoot after braking */
    }
    lcd_clrscr();
    lcd_puts_p(PSTR("slip: "));
    lcd_put_long(slip);
    _delay_ms(1000);
}

void doMove(int32_t length_puls) {
    cli();
    total_ls_pulses = 0;
    sei();
    OCR1A = PWM_TOP;
    PWM_START();
    lcd_show_p(PSTR("moving"), NULL);
    for (;;) {
        const int32_t t = total();
        if (PRESSED_D || !LIMIT_OK() || (length_puls != -1 && t >= length_puls)) break;
        /* Seed option (doMove, §2.5.3): the approach slowdown 2 leadscrew revolutions before the target, tested with
         * >= instead of the listing's equality, which can miss the one count. */
        if (length_puls > 0 && (t - length_puls + 2 * LS_PPR >= 0 || length_puls < 2 * LS_PPR)) OCR1A = PWM_SLOW;
    }
    PWM_STOP();
    doBrake();
    slip = length_puls == -1 ? 0 : total() - length_puls;
}
