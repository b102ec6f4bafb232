#include "tuning.h"

#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>
#include <util/delay.h>

#include "board.h"
#include "control.h"
#include "lcd.h"
#include "motion.h"

static volatile uint8_t periodcount;
static volatile uint8_t overflow;

ISR(TIMER2_COMP_vect, ISR_NOBLOCK) {
    if (periodcount == 0xFF) overflow = 1;
    periodcount++;
}

void tuning_mode(void) {
    uint8_t data[TUNING_PERIODS]; /* on the stack, as the seed (§2.5.3): no list exists during tuning */
    lcd_show_p(PSTR("tuning"), NULL);
    /* Seed option: the retry starts at OCR2 = 1 (the thesis gives only the final 3). At OCR2 = 0 a match comes every
     * 32 cycles, fewer than this ISR_NOBLOCK ISR takes (about 35 with its prologue), so the nested ISRs would
     * pile up until the stack overflows: the model's AVR core crashes there, as the chip would. */
    uint8_t ocr2 = 1;
    for (;;) {
        OCR2 = ocr2;
        overflow = 0;
        set_direction(LEFT);
        TCCR2 = 0x0B; /* CTC, clk/32 (§2.5.3) */
        TIMSK |= 1 << OCIE2;
        sei();
        uint16_t last = ls_pulses;
        OCR1A = PWM_TOP;
        PWM_START();
        periodcount = 0;
        for (uint16_t n = 0; n < TUNING_PERIODS && !overflow; ++n) {
            while (ls_pulses == last) {
            }
            data[n] = periodcount; /* the Timer2 counts since the previous motor pulse */
            periodcount = 0;
            last = ls_pulses;
        }
        PWM_STOP();
        TCCR2 = 0;
        doBrake();
        _delay_ms(1000);
        if (!overflow) break;
        ++ocr2;
    }
    eeprom_write_byte(EE_OCR2, ocr2);
    eeprom_write_block(data, EE_PERIODS, TUNING_PERIODS);
    lcd_show_p(PSTR("tuning done"), NULL);
}
