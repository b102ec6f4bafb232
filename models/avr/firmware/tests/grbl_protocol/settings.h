// The grbl settings this firmware knows ($N=value), with grbl 1.1's numbers and defaults (defaults.h).
#pragma once
#include <stdint.h>

typedef struct {
    uint8_t pulse_us;          // $0 step pulse, microseconds
    uint8_t idle_delay_ms;     // $1 (kept for $$; the drivers stay enabled, as grbl with $1 = 255)
    float max_spindle;         // $30 S for full laser power
    uint8_t laser_mode;        // $32
    float steps_per_mm[2];     // $100, $101
    float max_rate_mm_min[2];  // $110, $111
    float accel_mm_s2[2];      // $120, $121 (kept for $$: the firmware steps at the feed, without ramps)
} Settings;

extern Settings settings;

void settings_init(void);
// "$N=value" with text pointing at N: a grbl status code (0 = ok).
uint8_t settings_store(const char* text);
// "$$": every setting, one "$N=value" line each.
void settings_report(void);
