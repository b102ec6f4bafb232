// Our board for the firmware on an ATmega16 at 16 MHz (grbl has no ATmega16 port): STEP X/Y on PA0/PA1, DIR X/Y on
// PA2/PA3, the drivers' shared disable on PA4, the laser on OC2 (PD7), Timer2's only compare output. PORTA's only
// other function is the ADC, off from reset: these pins leave the USART (PD0/PD1, XCK PB0), INT0..INT2, the other
// compare outputs, ICP1, the SPI programming pins, JTAG and TOSC free (models/avr/core/pin_map.hpp,
// grbl_atmega16_pin_map()). The USART at grbl's 115200 Bd, as on the 328P.
#pragma once
#include <avr/io.h>

#define STEP_PORT PORTA
#define STEP_DDR DDRA
#define X_STEP_BIT PA0
#define Y_STEP_BIT PA1
#define STEP_MASK ((1 << X_STEP_BIT) | (1 << Y_STEP_BIT))

#define DIR_PORT PORTA
#define DIR_DDR DDRA
#define X_DIR_BIT PA2
#define Y_DIR_BIT PA3
#define DIR_MASK ((1 << X_DIR_BIT) | (1 << Y_DIR_BIT))

#define DISABLE_PORT PORTA
#define DISABLE_DDR DDRA
#define DISABLE_BIT PA4

#define LASER_DDR DDRD
#define LASER_BIT PD7  // OC2

// The USART (doc2466): the 328P's USART0 bits without the 0. UBRRH shares its address with UCSRC; a write with
// URSEL (bit 7) = 0, as every UBRR value here, goes to UBRRH.
#define SERIAL_UCSRA UCSRA
#define SERIAL_UCSRB UCSRB
#define SERIAL_UBRRH UBRRH
#define SERIAL_UBRRL UBRRL
#define SERIAL_UDR UDR
#define SERIAL_U2X U2X
#define SERIAL_RXEN RXEN
#define SERIAL_TXEN TXEN
#define SERIAL_RXCIE RXCIE
#define SERIAL_UDRIE UDRIE
#define SERIAL_RX_vect USART_RXC_vect
#define SERIAL_UDRE_vect USART_UDRE_vect

// Timer0 has one control register, TCCR0: normal mode (WGM01:00 = 00) is TCCR0 = its clock select alone. The
// single TIMSK and TIFR serve the three timers.
#define PULSE_TIMER_INIT()     \
    do {                       \
        TCCR0 = 0;             \
        TIMSK |= (1 << OCIE0); \
    } while (0)
#define PULSE_CLOCK TCCR0
#define PULSE_OCR OCR0
#define PULSE_vect TIMER0_COMP_vect

#define STEPPER_TIMSK_ENABLE() (TIMSK |= (1 << OCIE1A))
#define STEPPER_TIFR TIFR

// Timer2 fast PWM (WGM21:20 = 11) at clk/8 on OC2: 7.8 kHz at 16 MHz, as the 328P's; COM21 connects it.
#define LASER_TIMER_INIT() (TCCR2 = (1 << WGM21) | (1 << WGM20) | (1 << CS21))
#define LASER_TCCR TCCR2
#define LASER_COM_BIT COM21
#define LASER_OCR OCR2
