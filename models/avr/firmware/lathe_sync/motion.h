/* The passes (§2.5.3): doCut (one synchronised pass from the spindle index), doMove (full speed, no PID: the
 * retract or a plain move), doBrake (500 ms dynamic braking), with the slip bookkeeping of §2.5.1. */
#ifndef LATHE_SYNC_MOTION_H
#define LATHE_SYNC_MOTION_H

#include <stdint.h>

extern int32_t slip;
extern int32_t length_pulses; /* -1: unlimited */

void doBrake(void);
void doCut(void);
void doMove(int32_t length_puls);

#endif
