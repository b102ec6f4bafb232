/*
 * Firmware of seed 003 ("V38", AVR assembly in the thesis) re-implemented in C for avr-gcc: ATmega328P at
 * 16 MHz driving two DRV8825 through STEP (timer compare toggles), DIR and active-low EN, commanded one byte at a
 * time over USART0 by the PC program (CAD2G V42, models/host/core/cad2g).
 *
 * What the listings show and this firmware does (seed 003 §5.4, App. A2-A4):
 *  - Start loop: confirm, receive the command ID, dispatch to G00 / G01 / arc (G02 and G03 share it) / M30.
 *  - STEP X = OC0A (PD6, Timer0), STEP Y = OC2A (PB3, Timer2), CTC toggle; two matches per microstep.
 *  - G00: both axes at the v_max OCR, X counted in the Timer0 COMPA ISR, Y by polling OCF2A (dog-leg).
 *  - G01: only X counted, by polling OCF0A, T0 /1024; Y's distance follows from the OCR ratio.
 *  - Arcs: per chord DXL (8-bit X count), OCR0A, OCR2A, PORTB; the next chord is received while the current one
 *    runs, loaded when the ISR has counted X to zero; Y is never counted and keeps stepping until the reload;
 *    a PORTB byte with both EN bits high ends the arc.
 *  - An axis stops by its active-low EN bit; the PORTB start byte starts the motion.
 *  - M30: head off, sleep.
 *
 * Where the seed is silent or lost, this firmware decides (README.md):
 *  - Byte layout and order of every command, the confirm value 0x06, a confirm before every byte: protocol.h.
 *  - Timer prescalers: /1024 on both timers for every command (the PC computes with 1024). LASER_ENGRAVER_T2_CS110
 *    builds the G01 of App. A3 as listed (Timer2 CS = 110 = /256).
 *  - Every command starts from stopped timers, zero counts, clear flags and both STEP pins low (the receive and
 *    set-up blocks are missing from the seed); between chords the timers run on, as App. A4 shows.
 *  - The end of G01 disables both drivers (not shown in App. A3); every command ends with the timers stopped.
 *  - Zero counts do not wrap to 65536 steps: the axis is done.
 *  - The ISR saves SREG and its registers, and the half-pulse flag and a stale match flag are cleared at each
 *    chord load (the listings of App. A2 and A4 do neither).
 *  - Not implemented: homing on PD2/PD3 (Fig. 5.3 is missing; the simulated machine starts at its origin), the
 *    servo on Timer1/OC1A (the head is a laser on the HEADER bit PB1, set by each start byte), PORTC microstep
 *    outputs (the MODE pins are strapped on the driver boards, per scenario).
 */
#include <avr/io.h>

#include "avr_mcu_section.h"
#include "axes.h"
#include "commands.h"
#include "protocol.h"
#include "usart.h"

AVR_MCU(F_CPU, CNC_MCU_NAME);  /* simavr .mmcu section (cmake/AvrFirmware.cmake) */

int main(void) {
    axes_init();
    usart_init();
    for (;;) {
        switch (usart_confirm_receive()) {
            case LASER_ENGRAVER_CMD_G00: cmd_g00(); break;
            case LASER_ENGRAVER_CMD_G01: cmd_g01(); break;
            case LASER_ENGRAVER_CMD_G02:
            case LASER_ENGRAVER_CMD_G03: cmd_arc(); break;
            case LASER_ENGRAVER_CMD_M30: cmd_m30(); break;
            default: break;  /* an unknown ID is dropped: the Start loop asks for the next one */
        }
    }
}
