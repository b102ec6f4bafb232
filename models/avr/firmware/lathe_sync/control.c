#include "control.h"

#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>
#include <stdlib.h>

#include "board.h"
#include "lcd.h"
#include "ratio_list.h"

volatile int16_t Error;
volatile uint16_t ls_pulses;
volatile int32_t total_ls_pulses;
volatile uint16_t previous_ls_pulses;
volatile uint8_t sp_index;
struct listNode* volatile Ptr;

static struct listNode dummy = {0, &dummy}; /* §2.5.3 dummyPtr: a 1-node self-loop with info = 0 */
static struct listNode* list_start;

/* AVR221-style PID data (§2.5.3). */
static struct {
    int16_t lastError;
    int32_t sumError;
    uint16_t P_Factor, I_Factor, D_Factor;
    int16_t maxError;
    int32_t maxSumError;
} pid_st;

void pid_reset(void) {
    pid_st.sumError = 0;
    pid_st.lastError = 0;
}

static void pid_init(void) {
    pid_reset();
    pid_st.P_Factor = eeprom_read_word(EE_P);
    pid_st.I_Factor = eeprom_read_word(EE_I);
    pid_st.D_Factor = eeprom_read_word(EE_D);
    pid_st.maxError = (int16_t)(MAX_INT / (pid_st.P_Factor + 1));
    pid_st.maxSumError = MAX_I_TERM / (pid_st.I_Factor + 1);
}

void control_init(void) {
    Ptr = &dummy;
    MCUCR = 0x0A;  /* INT0 and INT1 on falling edges (§2.5.3) */
    GICR = 0xC0;
    TCCR0 = 0x08;  /* CTC, stopped */
    OCR0 = eeprom_read_byte(EE_OCR0);
    TIMSK |= 1 << OCIE0;
    ICR1 = PWM_TOP;
    TCCR1A = 0x02; /* WGM = 14: fast PWM, TOP = ICR1, clk/1: 7812.5 Hz */
    TCCR1B = 0x19;
    OCR1A = 0;
    DDRD |= (1 << PD0) | (1 << PD1) | (1 << PD5);
    PORTD |= (1 << PD6) | (1 << PD7); /* INDEX and LIMIT pulled up */
    pid_init();
}

/* Seed option: the seed declares every ISR ISR_NOBLOCK (§2.5.3), and its pulse counts are multi-byte variables
 * shared between nested ISRs (the thesis does not show their types). Two races follow, both seen on the model
 * (tests/lathe/lathe_thread_test.cpp):
 *   - INT1 preempting INT0 between its load and store of ls_pulses: INT0 then stores the interval's count + 1
 *     over the 0 INT1 wrote, the interval's pulses are subtracted twice and Error drops by a whole B(n);
 *   - INT0 preempting INT1 between its read and its clear of ls_pulses: that motor pulse is never subtracted.
 * PULSE_ISR_ATOMIC (the lathe_sync_atomic build) runs INT0 and INT1 with interrupts disabled and has the PID read
 * Error with interrupts disabled; the default keeps the seed's nesting. */
#ifdef PULSE_ISR_ATOMIC
#define PULSE_ISR_ATTR ISR_BLOCK
#else
#define PULSE_ISR_ATTR ISR_NOBLOCK
#endif

static int16_t read_error(void) {
#ifdef PULSE_ISR_ATOMIC
    cli();
    const int16_t e = Error;
    sei();
    return e;
#else
    return Error;
#endif
}

/* Motor encoder pulse (§2.5.3). */
ISR(INT0_vect, PULSE_ISR_ATTR) {
    ls_pulses++;
    total_ls_pulses++;
}

/* Spindle encoder pulse: add the list's B(n), subtract the motor pulses of the interval (§2.1, §2.5.3). */
ISR(INT1_vect, PULSE_ISR_ATTR) {
    sp_index++;
    if (sp_index == SP_PPR) sp_index = 0;
    Error += (int16_t)(Ptr->info - ls_pulses);
    previous_ls_pulses = ls_pulses;
    ls_pulses = 0;
    Ptr = Ptr->next;
}

/* PID tick every (OCR0 + 1) x 128 us (§2.5.3): position form, gains x32, output clamped to 0..PWM_TOP. */
ISR(TIMER0_COMP_vect, ISR_NOBLOCK) {
    const int16_t pid_error = read_error();
    int16_t p_term, d_term;
    int32_t i_term, ret, temp;
    if (pid_error > pid_st.maxError) p_term = MAX_INT;
    else if (pid_error < -pid_st.maxError) p_term = -MAX_INT;
    else p_term = (int16_t)(pid_st.P_Factor * pid_error);
    temp = pid_st.sumError + pid_error;
    if (temp > pid_st.maxSumError) {
        i_term = MAX_I_TERM;
        pid_st.sumError = pid_st.maxSumError;
    } else if (temp < -pid_st.maxSumError) {
        i_term = -MAX_I_TERM;
        pid_st.sumError = -pid_st.maxSumError;
    } else {
        pid_st.sumError = temp;
        i_term = (int32_t)pid_st.I_Factor * pid_st.sumError;
    }
    d_term = (int16_t)(pid_st.D_Factor * (pid_error - pid_st.lastError)); /* no clamp, as the seed */
    pid_st.lastError = pid_error;
    ret = ((int32_t)p_term + i_term + d_term) >> SCALING_FACTOR_BITS;
    if (ret > PWM_TOP) ret = PWM_TOP;
    else if (ret < 0) ret = 0;
    OCR1A = (uint16_t)ret;
}

struct listNode* makelist(uint16_t pitch) {
#ifdef MAKELIST_AS_PRINTED
    const ratio_fraction f = ratio_best_as_printed(pitch);
#else
    const ratio_fraction f = ratio_best(pitch);
#endif
    Ptr = &dummy; /* the INT1 ISR never sees a half-built list */
    struct listNode* head = NULL;
    struct listNode* tail = NULL;
    uint16_t rem = 0;
    for (uint16_t n = 0; n < f.den; ++n) {
        struct listNode* node = (struct listNode*)malloc(sizeof *node);
        if (node == NULL) {
            lcd_show_p(PSTR("out of memory"), NULL);
            break;
        }
        node->info = ratio_next(&rem, f.num, f.den);
        if (tail) tail->next = node;
        else head = node;
        tail = node;
    }
    if (head == NULL) return &dummy;
    tail->next = head;
    list_start = head;
    lcd_clrscr();
    lcd_puts_p(PSTR("List length: "));
    lcd_put_long(f.den);
    return head;
}

void freelist(void) {
    struct listNode* start = list_start;
    Ptr = &dummy;
    if (start == NULL) return;
    struct listNode* n = start->next;
    while (n != start) {
        struct listNode* next = n->next;
        free(n);
        n = next;
    }
    free(start);
    list_start = NULL;
}
