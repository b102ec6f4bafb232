// Interrupt-driven USART0 as grbl's serial.c does it: the RX complete ISR queues each byte, the main loop echoes
// the line when '\n' arrives, and the data register empty ISR (UDRIE0) sends from a ring buffer and disables
// itself when the buffer is empty. UBRR0 = 16, U2X0 = 0 (58 823.5 Bd).
#include <stdint.h>

#include "fw_test.h"

#define RING 64
static volatile uint8_t tx_buf[RING];
static volatile uint8_t tx_head;
static volatile uint8_t tx_tail;
static volatile uint8_t line[RING];
static volatile uint8_t line_len;
static volatile uint8_t line_done;

ISR(USART_RX_vect) {
    const uint8_t b = UDR0;
    if (line_len < RING) line[line_len++] = b;
    if (b == '\n') line_done = 1;
}

ISR(USART_UDRE_vect) {
    UDR0 = tx_buf[tx_tail];
    tx_tail = (uint8_t)((tx_tail + 1) % RING);
    if (tx_tail == tx_head) UCSR0B &= (uint8_t) ~(1 << UDRIE0);
}

int main(void) {
    UBRR0 = 16;
    UCSR0B = (1 << RXEN0) | (1 << TXEN0) | (1 << RXCIE0);
    sei();
    for (;;) {
        while (!line_done) {
        }
        cli();
        for (uint8_t i = 0; i < line_len; ++i) {
            tx_buf[tx_head] = line[i];
            tx_head = (uint8_t)((tx_head + 1) % RING);
        }
        line_len = 0;
        line_done = 0;
        UCSR0B |= (1 << UDRIE0);
        sei();
    }
}
