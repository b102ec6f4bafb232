/*
 * Wire protocol between the PC program (CAD2G) and the ATmega328P firmware (V38) of seed 003, shared by the
 * firmware (C) and the PC program core (C++, models/host/core/cad2g) so that the two cannot drift apart.
 *
 * Handshake (seed 003 App. A2 "RCALL Transmit //confirm; RCALL Receive"): before EVERY byte it reads, the MCU
 * transmits LASER_ENGRAVER_CONFIRM; the PC writes one byte per confirm it reads (writeSerialPort writes 1 byte).
 *
 * Commands (IDs: seed 003 Table 5.1). The byte layouts are this re-implementation's decision: the receive
 * blocks of the listings (App. A2-A4) are images missing from the seed; README.md gives the reasons.
 *   G00  00 | XL XH | YL YH | OCR  | PORTB        7 bytes: counts of both axes, one OCR (v_max) for both timers
 *   G01  01 | XL XH | OCR0A | OCR2A | PORTB       6 bytes: only X is counted (App. A3)
 *   G02  02 | chord... | terminator               per chord: DXL OCR0A OCR2A PORTB (App. A4: 8-bit DXL)
 *   G03  03 | chord... | terminator               terminator: a chord whose PORTB has both EN bits high
 *   M30  3B                                       head off, sleep
 * 16-bit counts go low byte first (STEPL before STEPH; the AVR is little-endian).
 *
 * The timer1-y build (LASER_ENGRAVER_TIMER1_Y, seed 003 §5.6 "move Y to Timer1"): Y's speed word is OCR1A, 16 bits,
 * sent low byte first like the counts, so each speed field for Y is one byte longer:
 *   G00  00 | XL XH | YL YH | OCR0A | OCR1AL OCR1AH | PORTB      9 bytes: X at v_max on Timer0, Y on Timer1
 *   G01  01 | XL XH | OCR0A | OCR1AL OCR1AH | PORTB              7 bytes
 *   chord   DXL OCR0A OCR1AL OCR1AH PORTB; terminator 00 FF FF FF PORTB
 * and STEP_Y moves to OC1A (PB1), the head to OC2A's pin (PB3): the two swap bits in the start byte.
 */
#pragma once

enum {
    LASER_ENGRAVER_CONFIRM = 0x06, /* this re-implementation's choice (the seed's value is lost): ASCII ACK */
    LASER_ENGRAVER_CMD_G00 = 0x00, /* seed 003 Table 5.1 */
    LASER_ENGRAVER_CMD_G01 = 0x01,
    LASER_ENGRAVER_CMD_G02 = 0x02,
    LASER_ENGRAVER_CMD_G03 = 0x03,
    LASER_ENGRAVER_CMD_M30 = 0x3B, /* '00111011' */
    LASER_ENGRAVER_BAUD = 57600    /* seed 003 §5.3.1: UBRR0L = 16000000/16/57600-1 */
};

/* PORTB, the "start byte" (seed 003 §5.2.6): PB7 '1' PB6 '1' PB5 Y_DIR PB4 Y_EN PB3 Y_STP PB2 X_EN PB1 HEADER
 * PB0 X_DIR. EN is active low (1 = driver disabled); DIR 0 = +, 1 = - (seed 003 §5.2.5). */
enum {
    LASER_ENGRAVER_PB_DIR_X = 0,
    LASER_ENGRAVER_PB_HEADER = 1,
    LASER_ENGRAVER_PB_EN_X = 2,
    LASER_ENGRAVER_PB_STEP_Y = 3,
    LASER_ENGRAVER_PB_EN_Y = 4,
    LASER_ENGRAVER_PB_DIR_Y = 5,
    LASER_ENGRAVER_PORTB_INPUTS = 0xC0 /* PB7, PB6 written '1' as in the seed's port table */
};

/* The timer1-y build's start byte: PB1 is OC1A (STEP_Y on Timer1, data sheet §14.3.1 "OC1A/PCINT1 - Port B,
 * Bit 1"), PB3 is OC2A's pin, where seed 003 §5.6 moves the head. */
enum {
    LASER_ENGRAVER_T1Y_PB_STEP_Y = 1,
    LASER_ENGRAVER_T1Y_PB_HEADER = 3
};
