/* HD44780 16x2 in 4-bit mode on PORTA (App. A.1: PA0..PA3 = D4..D7, PA4 = RS, PA5 = RW, PA6 = E), busy-flag
 * polling as the Fleury library the seed used. */
#ifndef LATHE_SYNC_LCD_H
#define LATHE_SYNC_LCD_H

#include <avr/pgmspace.h>
#include <stddef.h>
#include <stdint.h>

void lcd_init(void);
void lcd_clrscr(void);
void lcd_gotoxy(uint8_t x, uint8_t y);
void lcd_putc(char c);
void lcd_puts(const char* s);
void lcd_puts_p(const char* flash_s); /* a string in flash (PSTR): the RAM is kept for the B(n) list */
void lcd_put_long(int32_t v);
/* Clears, then line 1 and (if given) line 2, both in flash. */
void lcd_show_p(const char* line1, const char* line2);

#endif
