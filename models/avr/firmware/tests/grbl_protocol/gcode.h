// One line of G-code, as far as this firmware reads it: G0, G1, G17, G21, G90, G94, M2, M3, M4, M5, M30, X, Y, F, S, N.
// Anything else is grbl's error:20 (unsupported command).
#pragma once
#include <stdint.h>

void gcode_init(void);
// `line`: upper case, no spaces or comments. A grbl status code (0 = ok).
uint8_t gcode_execute(const char* line);
