/* The B(n) list of seed 002 (§2.1-2.2, makelist in §2.5.3): motor pulses per spindle pulse as a circular list of
 * integers whose running sum follows n * lambda, lambda = (pitch / LS_PITCH) * (LS_PPR / SP_PPR).
 * Shared by the firmware (avr-gcc, C) and the simulator's reference (host C++): one implementation of the
 * arithmetic, with the seed's integer types, so that both agree to the bit. */
#ifndef LATHE_SYNC_RATIO_LIST_H
#define LATHE_SYNC_RATIO_LIST_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RATIO_LS_PPR 780u      /* leadscrew pulses per rev: 30 slots x 1:26 gearbox (seed 002 §2.5.3 LS_PPR) */
#define RATIO_SP_PPR 40u       /* spindle pulses per rev (§2.5.3 SP_PPR) */
#define RATIO_LS_PITCH 3175u   /* leadscrew pitch, um (§2.5.3 LS_PITCH) */
#define RATIO_MAX_DEN 150u     /* largest list length: the "general memory limit" d_max (§2.2, §2.5.3) */

typedef struct {
    uint16_t num;      /* motor pulses per list period (bestx) */
    uint16_t den;      /* list length, spindle pulses (besty) */
    int32_t residual;  /* den * x - num * y, in units of 1/y motor pulses (bError at the chosen denominator) */
} ratio_fraction;

/* lambda = x / y for a pitch in 0.01 mm: x = LS_PPR * pitch * 10, y = SP_PPR * LS_PITCH = 127000. */
uint32_t ratio_x(uint16_t pitch_centi_mm);
uint32_t ratio_y(void);

/* The intended algorithm (§2.2's final procedure; makelist as printed does not do it): the denominator <= 150
 * whose rounded numerator leaves the smallest |residual|; ties keep the smaller denominator; an exact fraction stops
 * early. */
ratio_fraction ratio_best(uint16_t pitch_centi_mm);

/* makelist's search as printed (§2.5.3), with the missing ';' restored: `bError > y/2` compares int32 with
 * uint32, so a negative residual runs the subtraction loop until it wraps, and `bError < bestError` keeps the
 * most negative residual. 1.00 mm gives 46635/34. */
ratio_fraction ratio_best_as_printed(uint16_t pitch_centi_mm);

/* One list entry by truncation (§2.1, Bresenham form of §2.5.3): *rem is (n - 1) * num mod den before the call
 * and n * num mod den after; returns floor(n num / den) - floor((n - 1) num / den) as the seed's uint8 info. */
uint8_t ratio_next(uint16_t* rem, uint16_t num, uint16_t den);

#ifdef __cplusplus
}
#endif

#endif
