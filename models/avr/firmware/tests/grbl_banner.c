// A firmware that does not speak the seed 003 protocol, as the PC program meets grbl 1.1h given as avr.firmware:
// USART0 set up as grbl's serial_init does for BAUD_RATE 115200 (U2X0 on, UBRR0 = ((F_CPU / (4 x 115200)) - 1) / 2
// = 16: 117 647 Bd), then grbl's start-up message (report_init_message: "\r\nGrbl 1.1h ['$' for help]\r\n"), and
// no confirm byte ever: the received bytes are read and dropped (grbl would queue them as a G-code line and
// answer "ok" or "error" at its end, a newline that the seed 003 bytes need not contain).
#include <stdint.h>

#include "fw_test.h"

#define GRBL_BAUD 115200UL  // grbl config.h BAUD_RATE
#define GRBL_UBRR (((F_CPU / (4UL * GRBL_BAUD)) - 1) / 2)

static const char kBanner[] = "\r\nGrbl 1.1h ['$' for help]\r\n";

static void put(uint8_t b) {
    while (!(UCSR0A & (1 << UDRE0))) {
    }
    UDR0 = b;
}

int main(void) {
    UCSR0A = (1 << U2X0);
    UBRR0H = (uint8_t)(GRBL_UBRR >> 8);
    UBRR0L = (uint8_t)GRBL_UBRR;
    UCSR0B = (1 << RXEN0) | (1 << TXEN0);
    for (const char* c = kBanner; *c != '\0'; ++c) put((uint8_t)*c);
    for (;;) {
        if (UCSR0A & (1 << RXC0)) (void)UDR0;
    }
}
