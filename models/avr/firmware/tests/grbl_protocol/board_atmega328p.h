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

// USART0.
#define SERIAL_UCSRA UCSR0A
#define SERIAL_UCSRB UCSR0B
#define SERIAL_UBRRH UBRR0H
#define SERIAL_UBRRL UBRR0L
#define SERIAL_UDR UDR0
#define SERIAL_U2X U2X0
#define SERIAL_RXEN RXEN0
#define SERIAL_TXEN TXEN0
#define SERIAL_RXCIE RXCIE0
#define SERIAL_UDRIE UDRIE0
#define SERIAL_RX_vect USART_RX_vect
#define SERIAL_UDRE_vect USART_UDRE_vect

// Timer0 ends the STEP pulse at compare match A, in normal mode (TCCR0A = 0); TCCR0B holds its clock select.
#define PULSE_TIMER_INIT()      \
    do {                        \
        TCCR0A = 0;             \
        TIMSK0 = (1 << OCIE0A); \
    } while (0)
#define PULSE_CLOCK TCCR0B
#define PULSE_OCR OCR0A
#define PULSE_vect TIMER0_COMPA_vect

// Timer1 steps in CTC: its interrupt mask and flag registers.
#define STEPPER_TIMSK_ENABLE() (TIMSK1 = (1 << OCIE1A))
#define STEPPER_TIFR TIFR1

// Timer2 fast PWM (WGM2 = 011) at clk/8 on OC2A: COM2A1 connects it.
#define LASER_TIMER_INIT()                    \
    do {                                      \
        TCCR2A = (1 << WGM21) | (1 << WGM20); \
        TCCR2B = (1 << CS21);                 \
    } while (0)
#define LASER_TCCR TCCR2A
#define LASER_COM_BIT COM2A1
#define LASER_OCR OCR2A
