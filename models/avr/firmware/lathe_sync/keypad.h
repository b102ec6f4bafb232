/* 4x4 keypad matrix on PORTB (§2.5.3): PB7..PB4 = columns 1..4 (outputs), PB3..PB0 = rows 1..4 (inputs, pull-ups).
 * Keys: column 1 = 1, 4, 7, '*' (14); column 2 = 2, 5, 8, 0; column 3 = 3, 6, 9, '#' (15, the decimal point);
 * column 4 = A (10), B (11), C (12), D (13). After a scan column 4 is left low, so A..D can be polled. */
#ifndef LATHE_SYNC_KEYPAD_H
#define LATHE_SYNC_KEYPAD_H

#include <avr/io.h>
#include <stdint.h>

#define KEY_NONE 16
#define KEY_A 10
#define KEY_B 11
#define KEY_C 12
#define KEY_D 13
#define KEY_STAR 14
#define KEY_HASH 15

#define PRESSED_A (!(PINB & 0x08))
#define PRESSED_B (!(PINB & 0x04))
#define PRESSED_C (!(PINB & 0x02))
#define PRESSED_D (!(PINB & 0x01))

void keypad_init(void);           /* columns out, column 4 low; rows pulled up */
uint8_t read_key(void);           /* waits for a key; 1 ms settle per column, 200 ms debounce (§2.5.3) */
uint16_t read_num(void);          /* decimal entry, at most 2 decimals, D = enter: value x 100 (§2.5.3 read_numh) */
void debounce(void);              /* DEBOUNCE(): 200 ms */

#endif
