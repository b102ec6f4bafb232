#include "motion.h"

#include <avr/interrupt.h>
#include <util/atomic.h>

#include "board.h"
#include "report.h"
#include "serial.h"
#include "settings.h"

typedef struct {
    uint32_t steps[2];
    uint32_t step_events;  // the dominant axis's steps
    uint16_t ocr1a;
    uint8_t clock_select;  // TCCR1B's CS1 bits
    uint8_t dir_bits;
    uint8_t laser_ocr;
} Block;

static Block blocks[BLOCK_BUFFER_SIZE];
static volatile uint8_t block_head;
static volatile uint8_t block_tail;
static volatile uint8_t running;

// The stepper ISR's state: the pins to raise at the next interrupt (computed one interrupt ahead, as grbl does, so
// that the pins go out at the same cycle after the interrupt whatever Bresenham decides), the block being run and
// its Bresenham counters.
static uint8_t out_bits;
static Block* current;
static int32_t counter[2];
static uint32_t events_done;
static volatile int32_t position[2];
static volatile uint8_t idle_laser_ocr;  // the laser between moves: off in laser mode, M3's power outside it

// Timer0 in normal mode at clk/8 (0.5 us a count) ends the STEP pulse at its compare match.
static void pulse_timer_init(void) { PULSE_TIMER_INIT(); }

// Timer2 fast PWM, clk/8: 16 MHz / (8 x 256) = 7.8 kHz, grbl's spindle PWM on the 328P.
static void laser_init(void) {
    LASER_DDR |= (1 << LASER_BIT);
    LASER_TIMER_INIT();
    LASER_OCR = 0;
}

// Non-inverting OC2A / OC2 (COM = 10) while on; off, the pin is its PORT bit: low.
static void set_laser(uint8_t laser_ocr) {
    if (laser_ocr == 0) {
        LASER_TCCR &= (uint8_t) ~(1 << LASER_COM_BIT);
        return;
    }
    LASER_OCR = laser_ocr;
    LASER_TCCR |= (1 << LASER_COM_BIT);
}

void motion_init(void) {
    STEP_DDR |= STEP_MASK;
    DIR_DDR |= DIR_MASK;
    DISABLE_DDR |= (1 << DISABLE_BIT);
    DISABLE_PORT |= (1 << DISABLE_BIT);  // the drivers off until the first move
    TCCR1A = 0;
    TCCR1B = (1 << WGM12);  // CTC, TOP = OCR1A, stopped
    STEPPER_TIMSK_ENABLE();
    pulse_timer_init();
    laser_init();
}

void motion_laser(uint8_t laser_ocr) {
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
        idle_laser_ocr = laser_ocr;
        if (!running) set_laser(laser_ocr);
    }
}

ISR(PULSE_vect) {
    STEP_PORT &= (uint8_t)~STEP_MASK;
    PULSE_CLOCK = 0;
}

static uint8_t next_index(uint8_t i) { return (uint8_t)((i + 1) % BLOCK_BUFFER_SIZE); }

ISR(TIMER1_COMPA_vect) {
    if (out_bits != 0) {
        STEP_PORT |= out_bits;
        TCNT0 = 0;
        PULSE_CLOCK = (1 << CS01);
    }
    out_bits = 0;
    if (current == 0) {
        if (block_tail == block_head) {
            TCCR1B = (1 << WGM12);  // nothing to run: stop until motion_queue starts it again
            running = 0;
            set_laser(idle_laser_ocr);
            return;
        }
        current = &blocks[block_tail];
        DIR_PORT = (uint8_t)((DIR_PORT & ~DIR_MASK) | current->dir_bits);
        OCR1A = current->ocr1a;
        TCCR1B = (uint8_t)((1 << WGM12) | current->clock_select);
        STEPPER_TIFR = (1 << OCF1A);  // the matches of the wake-up's OCR1A = 0 while this ran
        set_laser(current->laser_ocr);
        counter[0] = counter[1] = -(int32_t)(current->step_events >> 1);
        events_done = 0;
    }
    for (uint8_t a = 0; a < 2; ++a) {
        counter[a] += (int32_t)current->steps[a];
        if (counter[a] > 0) {
            counter[a] -= (int32_t)current->step_events;
            out_bits |= (uint8_t)(1 << (a == 0 ? X_STEP_BIT : Y_STEP_BIT));
            const uint8_t negative = current->dir_bits & (uint8_t)(1 << (a == 0 ? X_DIR_BIT : Y_DIR_BIT));
            position[a] += negative ? -1 : 1;
        }
    }
    if (++events_done == current->step_events) {
        current = 0;
        block_tail = next_index(block_tail);
    }
}

static void wait_for_room(void) {
    while (next_index(block_head) == block_tail) {
        if (serial_status_request) {
            serial_status_request = 0;
            report_realtime_status();
        }
    }
}

// The clock select for the period: N = 1, 8 or 64 (CS1 = 001, 010, 011), the smallest whose OCR1A fits 16 bits.
static void set_period(Block* b, uint32_t cycles) {
    uint8_t cs = 1;
    uint8_t shift = 0;
    while ((cycles >> shift) > 65536UL && cs < 3) {
        ++cs;
        shift = (uint8_t)(shift + 3);
    }
    uint32_t counts = cycles >> shift;
    if (counts > 65536UL) counts = 65536UL;
    if (counts < 1) counts = 1;
    b->ocr1a = (uint16_t)(counts - 1);
    b->clock_select = cs;
}

void motion_queue(int32_t dx, int32_t dy, uint32_t cycles, uint8_t laser_ocr) {
    if (dx == 0 && dy == 0) return;
    wait_for_room();
    Block* b = &blocks[block_head];
    b->dir_bits = 0;
    if (dx < 0) b->dir_bits |= (1 << X_DIR_BIT);
    if (dy < 0) b->dir_bits |= (1 << Y_DIR_BIT);
    b->steps[0] = (uint32_t)(dx < 0 ? -dx : dx);
    b->steps[1] = (uint32_t)(dy < 0 ? -dy : dy);
    b->step_events = b->steps[0] > b->steps[1] ? b->steps[0] : b->steps[1];
    b->laser_ocr = laser_ocr;
    set_period(b, cycles);
    PULSE_OCR = (uint8_t)(settings.pulse_us * 2);
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
        block_head = next_index(block_head);
        if (!running) {
            // Wake up: the drivers on, and the first interrupt right away; it loads the block and sets DIR, its first
            // STEP goes out one period later.
            running = 1;
            DISABLE_PORT &= (uint8_t) ~(1 << DISABLE_BIT);
            TCNT1 = 0;
            OCR1A = 0;
            TCCR1B = (1 << WGM12) | (1 << CS10);
        }
    }
}

uint8_t motion_idle(void) { return !running && block_tail == block_head; }

void motion_position(int32_t out[2]) {
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
        out[0] = position[0];
        out[1] = position[1];
    }
}
