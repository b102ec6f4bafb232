// The board of grbl 1.1 on an ATmega328P (Arduino Uno pin-out, grbl's cpu_map.h for the 328P): STEP X/Y on PD2/PD3,
// DIR X/Y on PD5/PD6, the drivers' shared disable on PB0 (high disables: the DRV8825's nENBL), the laser on OC2A
// (PB3, Uno pin 11, grbl's variable-spindle PWM pin). USART0 at grbl's 115200 Bd.
#pragma once
#include <avr/io.h>

#define STEP_PORT PORTD
#define STEP_DDR DDRD
#define X_STEP_BIT PD2
#define Y_STEP_BIT PD3
#define STEP_MASK ((1 << X_STEP_BIT) | (1 << Y_STEP_BIT))

#define DIR_PORT PORTD
#define DIR_DDR DDRD
#define X_DIR_BIT PD5
#define Y_DIR_BIT PD6
#define DIR_MASK ((1 << X_DIR_BIT) | (1 << Y_DIR_BIT))

#define DISABLE_PORT PORTB
#define DISABLE_DDR DDRB
#define DISABLE_BIT PB0

#define LASER_DDR DDRB
#define LASER_BIT PB3  // OC2A

// grbl config.h BAUD_RATE; serial_init's U2X0 divisor: ((F_CPU / (4 x 115200)) - 1) / 2 = 16, 117 647 Bd.
#define SERIAL_BAUD 115200UL
#define SERIAL_UBRR (((F_CPU / (4UL * SERIAL_BAUD)) - 1) / 2)
