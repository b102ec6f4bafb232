/* USART0 as seed 003 §5.3.1 sets it up and App. A2 uses it: polled, blocking, no error checks. */
#pragma once
#include <stdint.h>

void usart_init(void);
/* seed 003 App. A2 "RCALL Transmit //confirm; RCALL Receive": the confirm byte, then one received byte. */
uint8_t usart_confirm_receive(void);
/* Two confirmed bytes, low byte first (protocol.h). */
uint16_t usart_confirm_receive_u16(void);
