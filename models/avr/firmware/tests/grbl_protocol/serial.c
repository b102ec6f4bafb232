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
    SERIAL_UCSRA = (1 << SERIAL_U2X);
    SERIAL_UBRRH = (uint8_t)(SERIAL_UBRR >> 8);
    SERIAL_UBRRL = (uint8_t)SERIAL_UBRR;
    SERIAL_UCSRB = (1 << SERIAL_RXEN) | (1 << SERIAL_TXEN) | (1 << SERIAL_RXCIE);
}

// A byte that finds the buffer full is dropped: a character-counting sender never sends one.
ISR(SERIAL_RX_vect) {
    const uint8_t byte = SERIAL_UDR;
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

ISR(SERIAL_UDRE_vect) {
    SERIAL_UDR = tx_buffer[tx_tail];
    tx_tail = (uint8_t)((tx_tail + 1) % TX_BUFFER_SIZE);
    if (tx_tail == tx_head) SERIAL_UCSRB &= (uint8_t) ~(1 << SERIAL_UDRIE);
}

void serial_write(uint8_t byte) {
    const uint8_t next = (uint8_t)((tx_head + 1) % TX_BUFFER_SIZE);
    while (next == tx_tail) {
    }
    tx_buffer[tx_head] = byte;
    tx_head = next;
    SERIAL_UCSRB |= (1 << SERIAL_UDRIE);
}

void serial_print(const char* text) {
    while (*text != '\0') serial_write((uint8_t)*text++);
}
