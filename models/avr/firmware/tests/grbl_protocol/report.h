// What the firmware prints: numbers with grbl's three decimals, "ok" / "error:N", the status report.
#pragma once
#include <stdint.h>

void report_uint(uint32_t value);
void report_float(float value);  // three decimals, as grbl's N_DECIMAL_COORDVALUE_MM
void report_status_message(uint8_t status);
// "<Idle|MPos:x,y,0.000|FS:f,s>" or "<Run|...>": the machine position from the step counts.
void report_realtime_status(void);
