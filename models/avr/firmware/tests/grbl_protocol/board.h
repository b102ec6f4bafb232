// The board the firmware is built for, by the MCU avr-gcc's -mmcu names: its pins and the register names of its
// USART and timers (the C source is the same for both).
#pragma once
#if defined(__AVR_ATmega16__)
#include "board_atmega16.h"
#elif defined(__AVR_ATmega328P__)
#include "board_atmega328p.h"
#else
#error "grbl_protocol is built for the ATmega328P or the ATmega16"
#endif

// grbl config.h BAUD_RATE; serial_init's U2X divisor: ((F_CPU / (4 x 115200)) - 1) / 2 = 16 at 16 MHz, 117 647 Bd.
#define SERIAL_BAUD 115200UL
#define SERIAL_UBRR (((F_CPU / (4UL * SERIAL_BAUD)) - 1) / 2)
