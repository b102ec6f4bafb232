// Shared by the timer/USART fidelity test firmwares: the simavr .mmcu section, the end-of-test idiom, and
// markers. A marker is a pin write whose cycle the test reads off a SystemC port; the register write under test
// sits in the same inline-asm block right after it, so its cycle is known exactly: `out` takes 1 cycle, `sts` 2
// (AVR instruction set manual), and the model does an instruction's I/O at the instruction's first cycle.
#pragma once
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

#include "avr_mcu_section.h"

AVR_MCU(F_CPU, CNC_MCU_NAME);

// cli + sleep: simavr stops the CPU (cpu_Done); the model keeps the timers and USART running.
static inline void fw_end(void) {
    cli();
    sleep_enable();
    sleep_cpu();
}

// Marker pins on PORTB: PB0 (dir_x in the default pin map), PB5 (dir_y), PB4 (en_y).
#define MARK_A (1 << PB0)
#define MARK_B (1 << PB5)
#define MARK_C (1 << PB4)
