/* The synchronisation core (§2.1, §2.5.3): the motor (INT0) and spindle (INT1) pulse ISRs, the B(n) list and
 * the Timer0 PID. */
#ifndef LATHE_SYNC_CONTROL_H
#define LATHE_SYNC_CONTROL_H

#include <stdint.h>

struct listNode {
    uint8_t info;
    struct listNode* next;
};

extern volatile int16_t Error;
extern volatile uint16_t ls_pulses;
extern volatile int32_t total_ls_pulses;
extern volatile uint16_t previous_ls_pulses;
extern volatile uint8_t sp_index;
extern struct listNode* volatile Ptr;

void control_init(void);   /* INT0/INT1 falling edges, Timer0 CTC (stopped), Timer1 fast PWM, PID gains */
void pid_reset(void);      /* sumError = lastError = 0 */
/* makelist (§2.5.3): the intended search by default, the printed one with -DMAKELIST_AS_PRINTED (seed option: the
 * listing's defects, ratio_list.h); shows the list length and error on the LCD. Returns the list (dummy on out of
 * memory). */
struct listNode* makelist(uint16_t pitch);
void freelist(void);

#endif
