// A firmware that keeps the seed 003 handshake and does nothing else: at the seed's rate (UBRR0 = 16) it sends
// the confirm byte before every byte it reads and drops the byte. The PC program sends the whole job, no STEP
// comes out, and M30 never puts the MCU to sleep: a job that cannot finish, for the run's own time limit.
// Built with CONFIRMS = n it confirms n bytes and then hangs: a firmware that stops answering in mid-job.
#include <stdint.h>

#include "../laser_engraver/protocol.h"
#include "fw_test.h"

#define UBRR_VALUE (F_CPU / 16 / LASER_ENGRAVER_BAUD - 1)  // as the seed's firmware: 16 (58 823.5 Bd)
#ifndef CONFIRMS
#define CONFIRMS 0  // 0: every byte
#endif

static void confirm_and_drop(void) {
    while (!(UCSR0A & (1 << UDRE0))) {
    }
    UDR0 = LASER_ENGRAVER_CONFIRM;
    while (!(UCSR0A & (1 << RXC0))) {
    }
    (void)UDR0;
}

int main(void) {
    UBRR0H = 0;
    UBRR0L = UBRR_VALUE;
    UCSR0B = (1 << RXEN0) | (1 << TXEN0);
#if CONFIRMS == 0
    for (;;) confirm_and_drop();
#else
    for (uint8_t n = 0; n < CONFIRMS; ++n) confirm_and_drop();
    for (;;) {
    }
#endif
}
