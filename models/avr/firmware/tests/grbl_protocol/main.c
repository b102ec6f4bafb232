// A firmware of our own that speaks grbl 1.1's line protocol over USART0 (its start-up message, "$N=value", "$$",
// the real-time "?", "ok" / "error:N" per line) and steps two axes with Bresenham in a Timer1 ISR, on grbl's
// pins: the grbl architecture's G-code sender and its checks run on it without grbl's source. What it reads is in
// gcode.h; what it leaves out of grbl (acceleration, arcs, homing, alarms, feed hold) in the README of
// sim/architectures/grbl. With nothing to read it sleeps in Idle mode until an interrupt (grbl polls instead): the
// stepper interrupt then always finds the CPU asleep and answers in the same 8 cycles, so its STEP edges keep the
// Bresenham pattern exactly.
#include <avr/interrupt.h>
#include <avr/sleep.h>

#include "avr_mcu_section.h"
#include "gcode.h"
#include "motion.h"
#include "report.h"
#include "serial.h"
#include "settings.h"
#include "status.h"

AVR_MCU(F_CPU, CNC_MCU_NAME);

#define LINE_BUFFER_SIZE 80  // grbl's for the 328P

static char line[LINE_BUFFER_SIZE];

static uint8_t execute_line(const char* text) {
    if (text[0] == '\0') return STATUS_OK;  // an empty line, as grbl: "ok" for syncing
    if (text[0] != '$') return gcode_execute(text);
    if (text[1] == '$' && text[2] == '\0') {
        settings_report();
        return STATUS_OK;
    }
    return settings_store(text + 1);
}

int main(void) {
    settings_init();
    gcode_init();
    serial_init();
    motion_init();
    sei();
    serial_print("\r\nGrbl 1.1 cncsim-test ['$' for help]\r\n");
    uint8_t length = 0;
    uint8_t overflow = 0;
    uint8_t in_comment = 0;
    set_sleep_mode(SLEEP_MODE_IDLE);
    sleep_enable();
    for (;;) {
        // sei; sleep: the instruction after SEI runs before any interrupt, so a byte that came after the check
        // wakes the CPU from this sleep instead of waiting for the next one (avr-libc <avr/sleep.h>).
        cli();
        if (!serial_status_request && !serial_available()) {
            sei();
            sleep_cpu();
        }
        sei();
        if (serial_status_request) {
            serial_status_request = 0;
            report_realtime_status();
        }
        const uint8_t c = serial_read();
        if (c == SERIAL_NO_DATA) continue;
        if (c == '\n' || c == '\r') {
            line[length] = '\0';
            report_status_message(overflow ? STATUS_OVERFLOW : execute_line(line));
            length = 0;
            overflow = 0;
            in_comment = 0;
        } else if (in_comment) {
            if (c == ')' && in_comment == 1) in_comment = 0;
        } else if (c == '(') {
            in_comment = 1;
        } else if (c == ';') {
            in_comment = 2;  // to the end of the line
        } else if (c > ' ') {
            if (length + 1 >= LINE_BUFFER_SIZE) overflow = 1;
            else line[length++] = (char)(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
        }
    }
}
