// A firmware without simavr's .mmcu section, as grbl's Makefile and the Arduino IDE build theirs: only avr-libc's
// .note.gnu.avr.deviceinfo names its MCU.
#include <avr/io.h>

int main(void) {
    DDRB = 1;
    for (;;) PORTB ^= 1;
}
