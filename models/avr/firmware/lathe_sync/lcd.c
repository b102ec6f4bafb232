#include "lcd.h"

#include <avr/io.h>
#include <stdlib.h>
#include <util/delay.h>

#define LCD_RS (1 << PA4)
#define LCD_RW (1 << PA5)
#define LCD_E (1 << PA6)
#define LCD_DATA 0x0F

/* E pulse: PWEH >= 230 ns (HD44780 datasheet), two cycles at 8 MHz with the surrounding instructions. */
static void toggle_e(void) {
    PORTA |= LCD_E;
    __asm__ volatile("nop\n\tnop\n\t");
    PORTA &= (uint8_t)~LCD_E;
}

static uint8_t read_nibble(void) {
    PORTA |= LCD_E;
    __asm__ volatile("nop\n\tnop\n\t");
    const uint8_t v = PINA & LCD_DATA;
    PORTA &= (uint8_t)~LCD_E;
    return v;
}

static void wait_busy(void) {
    DDRA &= (uint8_t)~LCD_DATA;
    PORTA = (uint8_t)((PORTA & ~(LCD_RS | LCD_DATA)) | LCD_RW);
    uint8_t busy;
    do {
        busy = (uint8_t)(read_nibble() & 0x08); /* D7 of the high nibble */
        (void)read_nibble();
    } while (busy);
    PORTA &= (uint8_t)~LCD_RW;
    DDRA |= LCD_DATA;
}

static void write_nibble(uint8_t n) {
    PORTA = (uint8_t)((PORTA & ~LCD_DATA) | (n & LCD_DATA));
    toggle_e();
}

static void write_byte(uint8_t v, uint8_t rs) {
    wait_busy();
    if (rs) PORTA |= LCD_RS;
    else PORTA &= (uint8_t)~LCD_RS;
    write_nibble((uint8_t)(v >> 4));
    write_nibble(v);
}

void lcd_init(void) {
    DDRA = LCD_DATA | LCD_RS | LCD_RW | LCD_E;
    PORTA = 0;
    _delay_ms(16); /* HD44780 power-on: > 15 ms */
    write_nibble(0x03);
    _delay_ms(5);
    write_nibble(0x03);
    _delay_us(100);
    write_nibble(0x03);
    _delay_us(100);
    write_nibble(0x02); /* 4-bit interface */
    _delay_us(100);
    write_byte(0x28, 0); /* 4-bit, 2 lines, 5x7 */
    write_byte(0x08, 0); /* display off */
    write_byte(0x01, 0); /* clear */
    write_byte(0x06, 0); /* increment, no shift */
    write_byte(0x0C, 0); /* display on, no cursor */
}

void lcd_clrscr(void) { write_byte(0x01, 0); }

void lcd_gotoxy(uint8_t x, uint8_t y) { write_byte((uint8_t)(0x80 | (y ? 0x40 : 0x00) | x), 0); }

void lcd_putc(char c) {
    if (c == '\n') {
        lcd_gotoxy(0, 1);
        return;
    }
    write_byte((uint8_t)c, 1);
}

void lcd_puts(const char* s) {
    while (*s) lcd_putc(*s++);
}

void lcd_puts_p(const char* flash_s) {
    char c;
    while ((c = (char)pgm_read_byte(flash_s++)) != 0) lcd_putc(c);
}

void lcd_put_long(int32_t v) {
    char buf[12];
    ltoa(v, buf, 10);
    lcd_puts(buf);
}

void lcd_show_p(const char* line1, const char* line2) {
    lcd_clrscr();
    lcd_puts_p(line1);
    if (line2) {
        lcd_gotoxy(0, 1);
        lcd_puts_p(line2);
    }
}
