#include "commands.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

#include "axes.h"
#include "pins.h"
#include "usart.h"

/* App. A3 as listed writes TCCR2B = 0b110: /256 on Timer2 (the comment says 128), while the PC program computes
 * OCR2A with 1024. The default build uses /1024 so that Y runs at the speed the PC asked for; the
 * laser_engraver_t2cs110 build keeps the listing's value (README.md). */
#ifdef LASER_ENGRAVER_T2_CS110
#define Y_CS_G01 T2_CS_256
#else
#define Y_CS_G01 Y_CS_RUN
#endif

/* Y's speed word: OCR2A (8 bits), or in the timer1-y build OCR1A (16 bits, low byte first: protocol.h). */
#ifdef LASER_ENGRAVER_TIMER1_Y
#define receive_ocr_y() usart_confirm_receive_u16()
#else
#define receive_ocr_y() usart_confirm_receive()
#endif

void cmd_g00(void) {
    const uint16_t count_x = usart_confirm_receive_u16();
    const uint16_t count_y = usart_confirm_receive_u16();
    const uint8_t ocr = usart_confirm_receive();  /* v_max for both axes (eq. 4.73) */
#ifdef LASER_ENGRAVER_TIMER1_Y
    const ocr_y_t ocr_y = receive_ocr_y(); /* v_max on Timer1: its own word */
#else
    const ocr_y_t ocr_y = ocr;
#endif
    const uint8_t portb = usart_confirm_receive(); /* "//6th PORTB" */
    axes_prepare(ocr, ocr_y);
    axes_arm_x_interrupt(count_x);
    axes_start(portb, Y_CS_RUN);
    sei();
    axes_count_y_polling(count_y);
    while (axes_x_running()) {  /* App. A2 Decrease_x: the longer axis finishes last (dog-leg) */
    }
    cli();
    axes_finish();
}

void cmd_g01(void) {
    const uint16_t count_x = usart_confirm_receive_u16();
    const uint8_t ocr_x = usart_confirm_receive();
    const ocr_y_t ocr_y = receive_ocr_y();
    const uint8_t portb = usart_confirm_receive();
    axes_prepare(ocr_x, ocr_y);
    axes_start(portb, Y_CS_G01);
#ifdef LASER_ENGRAVER_TIMER1_Y
    /* dx = 0 (X disabled): the count is Y's, on its own timer; the seed's X timebase (§5.4.2 note 1) would hold Y
     * to X's 8-bit rate. */
    if (portb & _BV(LASER_ENGRAVER_PB_EN_X)) {
        axes_count_y_polling(count_x);
    } else {
        axes_count_x_polling(count_x);
    }
#else
    axes_count_x_polling(count_x);
#endif
    axes_finish();  /* App. A3 does not show how G01 ends: both axes stop with X */
}

void cmd_arc(void) {
    uint8_t first = 1;
    for (;;) {
        /* Received while the previous chord runs ("Store Data to memory not to working registers"). */
        const uint8_t dxl = usart_confirm_receive();
        const uint8_t ocr_x = usart_confirm_receive();
        const ocr_y_t ocr_y = receive_ocr_y();
        const uint8_t portb = usart_confirm_receive();
        while (axes_x_running()) {  /* App. A4 "loop: CPI STEPL,0; BRNE loop"; Y keeps stepping meanwhile */
        }
        cli();
        if (first) axes_prepare(ocr_x, ocr_y);
        axes_load_chord(dxl, ocr_x, ocr_y, portb);
        if (first) axes_run_timers(Y_CS_RUN);
        first = 0;
        sei();
        if ((portb & PORTB_EN_BOTH) == PORTB_EN_BOTH) break;  /* App. A4: SBIC PORTB,PB4; SBIS PORTB,PB2 */
    }
    cli();
    axes_finish();
}

void cmd_m30(void) {
    axes_finish();
    PORTB &= ~_BV(PB_HEADER);
    set_sleep_mode(SLEEP_MODE_PWR_DOWN);  /* the seed's SLEEP mode is unspecified */
    sleep_enable();
    sleep_cpu();  /* interrupts are off: the MCU sleeps until reset */
}
