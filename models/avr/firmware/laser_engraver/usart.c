#include "usart.h"

#include <avr/io.h>

#include "protocol.h"

/* seed 003 §5.3.1: LDI TEMP,16000000/16/57600-1 (integer arithmetic: 16) -> 16e6 / (16 x 17) = 58 823.5 Bd,
 * +2.12 % against the 57 600 Bd the PC asks for. U2X0 stays 0, UBRR0H stays 0. */
#define UBRR_VALUE (F_CPU / 16 / LASER_ENGRAVER_BAUD - 1)

void usart_init(void) {
    /* The seed writes UBRR0L, UCSR0B, UCSR0C in that order; UCSR0C first changes nothing on the chip (its reset
     * value is already 8N1) and keeps simulators that latch the rate at the UBRR write (simavr 1.6 does) right. */
    UCSR0C = _BV(UCSZ01) | _BV(UCSZ00); /* 0x06: asynchronous, 8 data bits, no parity, 1 stop bit */
    UBRR0H = 0;
    UBRR0L = UBRR_VALUE;
    UCSR0B = _BV(RXEN0) | _BV(TXEN0);   /* 0x18: no USART interrupts */
}

/* seed 003 "Transmit": LDS UCSR0A; SBRS UDRE0; RJMP Transmit; STS UDR0 */
static void transmit(uint8_t byte) {
    while (!(UCSR0A & _BV(UDRE0))) {
    }
    UDR0 = byte;
}

/* seed 003 "Receive": LDS UCSR0A; SBRS RXC0; RJMP Receive; LDS UDR0 (no FE0/DOR0 check, as in the seed) */
static uint8_t receive(void) {
    while (!(UCSR0A & _BV(RXC0))) {
    }
    return UDR0;
}

uint8_t usart_confirm_receive(void) {
    transmit(LASER_ENGRAVER_CONFIRM);
    return receive();
}

uint16_t usart_confirm_receive_u16(void) {
    const uint8_t low = usart_confirm_receive();
    const uint8_t high = usart_confirm_receive();
    return (uint16_t)((uint16_t)high << 8 | low);
}
