/* tuning_mode (§2.5.3, the run of §4.3): the motor from rest at 100 % duty (LEFT), 400 motor-encoder periods
 * counted in Timer2 compare interrupts (CTC, clk/32), retried with OCR2 + 1 while a period overflows the uint8
 * count, then copied to EEPROM (OCR2 at byte 18, the periods from byte 20). */
#ifndef LATHE_SYNC_TUNING_H
#define LATHE_SYNC_TUNING_H

void tuning_mode(void);

#endif
