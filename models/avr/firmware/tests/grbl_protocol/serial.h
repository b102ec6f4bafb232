// USART0 with interrupt-driven ring buffers, as grbl's serial.c: the receive buffer holds RX_BUFFER_SIZE bytes (the
// window a character-counting sender fills), '?' is taken out of the stream in the receive ISR as a real-time
// status request.
#pragma once
#include <stdint.h>

#define RX_BUFFER_SIZE 128  // grbl config: the sender's character-counting window
#define SERIAL_NO_DATA 0xFF

void serial_init(void);
// The next received byte, or SERIAL_NO_DATA.
uint8_t serial_read(void);
// Bytes received and not read yet (nonzero: some).
uint8_t serial_available(void);
void serial_write(uint8_t byte);
void serial_print(const char* text);
// Set by the receive ISR when '?' arrives; the main loop answers it and clears it.
extern volatile uint8_t serial_status_request;
