#include "serial.h"

#include <avr/interrupt.h>

#include "board.h"

#define TX_BUFFER_SIZE 64

static volatile uint8_t rx_buffer[RX_BUFFER_SIZE];
static volatile uint8_t rx_head;
static volatile uint8_t rx_tail;
static volatile uint8_t tx_buffer[TX_BUFFER_SIZE];
static volatile uint8_t tx_head;
static volatile uint8_t tx_tail;
volatile uint8_t serial_status_request;

void serial_init(void) {
    UCSR0A = (1 << U2X0);
    UBRR0H = (uint8_t)(SERIAL_UBRR >> 8);
    UBRR0L = (uint8_t)SERIAL_UBRR;
    UCSR0B = (1 << RXEN0) | (1 << TXEN0) | (1 << RXCIE0);
}

// A byte that finds the buffer full is dropped: a character-counting sender never sends one.
ISR(USART_RX_vect) {
    const uint8_t byte = UDR0;
    if (byte == '?') {
        serial_status_request = 1;
        return;
    }
    const uint8_t next = (uint8_t)((rx_head + 1) % RX_BUFFER_SIZE);
    if (next != rx_tail) {
        rx_buffer[rx_head] = byte;
        rx_head = next;
    }
}

uint8_t serial_available(void) { return rx_head != rx_tail; }

uint8_t serial_read(void) {
    if (rx_tail == rx_head) return SERIAL_NO_DATA;
    const uint8_t byte = rx_buffer[rx_tail];
    rx_tail = (uint8_t)((rx_tail + 1) % RX_BUFFER_SIZE);
    return byte;
}

ISR(USART_UDRE_vect) {
    UDR0 = tx_buffer[tx_tail];
    tx_tail = (uint8_t)((tx_tail + 1) % TX_BUFFER_SIZE);
    if (tx_tail == tx_head) UCSR0B &= (uint8_t) ~(1 << UDRIE0);
}

void serial_write(uint8_t byte) {
    const uint8_t next = (uint8_t)((tx_head + 1) % TX_BUFFER_SIZE);
    while (next == tx_tail) {
    }
    tx_buffer[tx_head] = byte;
    tx_head = next;
    UCSR0B |= (1 << UDRIE0);
}

void serial_print(const char* text) {
    while (*text != '\0') serial_write((uint8_t)*text++);
}
