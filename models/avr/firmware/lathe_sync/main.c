/* Seed 002's firmware (§2.5.3), our C re-implementation for the ATmega16 at 8 MHz. Power-up keys: D held
 * = configuration, B held = tuning_mode, C held = test mode (not re-implemented: it only displays counters);
 * then the main menu "1: cut 2: move" (§2.5.2, §2.5.3). */
#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>

#include "avr_mcu_section.h"
#include "board.h"
#include "control.h"
#include "keypad.h"
#include "lcd.h"
#include "motion.h"
#include "tuning.h"

AVR_MCU(F_CPU, CNC_MCU_NAME);

/* The seed does not give its OCR0 or integer gains (§4.3 reports the continuous ones); the defaults are our
 * discretisation of §4.3's Simulink autotune (Kp 72.0371, Ki 82.6077, Kd 0.6721) at OCR0 = 39, T_s = 40 x 128 us
 * = 5.12 ms: P = round(72.04 x 32) = 2305, I = round(Ki T_s 32) = 14 (13.5), D = round(Kd / T_s x 32) = 4201. */
uint8_t ee_image[10] EEMEM = {0xFF, 0xFF, 0xFF, 39, 2305 & 0xFF, 2305 >> 8, 14, 0, 4201 & 0xFF, 4201 >> 8};

static uint16_t ask(const char* prompt) {
    lcd_show_p(prompt, NULL);
    lcd_gotoxy(0, 1);
    return read_num();
}

static void configuration(void) {
    eeprom_write_byte(EE_OCR0, (uint8_t)(ask(PSTR("time intervals (ms/8)")) / 100));
    eeprom_write_word(EE_P, ask(PSTR("Kp*32")) / 100);
    eeprom_write_word(EE_I, ask(PSTR("Ki*32")) / 100);
    eeprom_write_word(EE_D, ask(PSTR("Kd*32")) / 100);
}

static int32_t pulses_of(uint16_t length_centi_mm) {
    const int32_t p = (int32_t)LS_PPR * length_centi_mm * 10 / LS_PITCH; /* truncation, as §2.5.3 */
    return p == 0 ? -1 : p;
}

/* Waits for OK (D: returns 1) or cancel (C: returns 0), our reading of the wait loops of §2.5.3's main(), whose
 * braces are garbled as printed. */
static uint8_t wait_ok(const char* prompt) {
    lcd_show_p(prompt, NULL);
    for (;;) {
        if (PRESSED_C) {
            debounce();
            return 0;
        }
        if (PRESSED_D) {
            debounce();
            return 1;
        }
    }
}

static void menu_move(void) {
    const int32_t len = pulses_of(ask(PSTR("length (mm)")));
    lcd_show_p(PSTR("1:left 2:right"), NULL);
    set_direction(read_key() == 2 ? RIGHT : LEFT);
    sei();
    if (wait_ok(PSTR("OK to move"))) doMove(len);
}

static void menu_cut(void) {
    lcd_show_p(PSTR("1:coarse 2:fine"), PSTR("3:thread"));
    const uint8_t k = read_key();
    const uint16_t pitch = k == 3 ? ask(PSTR("pitch (mm)")) : k == 2 ? 4 : 8;
    Ptr = makelist(pitch);
    lcd_show_p(PSTR("1:Right handed"), PSTR("2:Left handed"));
    set_direction(read_key() == 2 ? RIGHT : LEFT);
    length_pulses = pulses_of(ask(PSTR("length (mm)")));
    sei();
    slip = 0;
    for (;;) {
        if (!wait_ok(PSTR("press OK to cut"))) break;
        doCut();
        if (!wait_ok(PSTR("OK to retract"))) break;
        const uint8_t d = direction();
        set_direction((uint8_t)~d);
        doMove(length_pulses + slip);
        set_direction(d);
    }
    freelist();
}

int main(void) {
    keypad_init();
    lcd_init();
    control_init();
    if (PRESSED_D) configuration();
    else if (PRESSED_B) tuning_mode();
    lcd_show_p(PSTR(" E-LEADSCREW "), PSTR("kostas Karouzos"));
    sei();
    for (;;) {
        lcd_show_p(PSTR("1: cut 2: move"), NULL);
        const uint8_t k = read_key();
        if (k == 1) menu_cut();
        else if (k == 2) menu_move();
    }
}
