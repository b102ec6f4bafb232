#include "keypad.h"

#include <util/delay.h>

#include "lcd.h"

static const uint8_t kKeys[4][4] = {
    {1, 4, 7, KEY_STAR}, {2, 5, 8, 0}, {3, 6, 9, KEY_HASH}, {KEY_A, KEY_B, KEY_C, KEY_D}};

void debounce(void) { _delay_ms(200); }

void keypad_init(void) {
    DDRB = 0xF0;
    PORTB = 0xEF; /* columns 1..3 high, column 4 low, row pull-ups on */
}

static uint8_t scan(void) {
    for (uint8_t col = 0; col < 4; ++col) {
        PORTB = (uint8_t)(0xFF & ~(0x80 >> col));
        _delay_ms(1);
        const uint8_t rows = PINB & 0x0F;
        for (uint8_t row = 0; row < 4; ++row) {
            if (!(rows & (0x08 >> row))) {
                PORTB = 0xEF;
                return kKeys[col][row];
            }
        }
    }
    PORTB = 0xEF;
    return KEY_NONE;
}

uint8_t read_key(void) {
    uint8_t k;
    while ((k = scan()) == KEY_NONE) {
    }
    debounce();
    return k;
}

uint16_t read_num(void) {
    uint16_t value = 0;
    int8_t decimals = -1; /* -1: no point yet */
    for (;;) {
        const uint8_t k = read_key();
        if (k == KEY_D) break;
        if (k == KEY_HASH && decimals < 0) {
            decimals = 0;
            lcd_putc('.');
        } else if (k <= 9 && decimals < 2) {
            value = (uint16_t)(value * 10 + k);
            if (decimals >= 0) ++decimals;
            lcd_putc((char)('0' + k));
        }
    }
    for (int8_t d = decimals < 0 ? 0 : decimals; d < 2; ++d) value = (uint16_t)(value * 10);
    return value;
}
