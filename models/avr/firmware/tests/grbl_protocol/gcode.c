#include "gcode.h"

#include <math.h>
#include <stdlib.h>

#include "motion.h"
#include "settings.h"
#include "status.h"

// grbl's highest step rate on a 16 MHz 328P is 30 kHz (its documentation): the period is held to 533 cycles.
#define MIN_STEP_CYCLES 533UL

float gcode_feed_mm_min;
float gcode_power;
static uint8_t motion_mode;  // 0: G0, 1: G1
static uint8_t laser_on;     // M3/M4
static int32_t planned_steps[2];

void gcode_init(void) {
    gcode_feed_mm_min = 0.0f;
    gcode_power = 0.0f;
    motion_mode = 0;
    laser_on = 0;
}

// OC2A's compare value for S: S / $30 of the full scale, 255 at or above $30 (0 keeps the pin low).
static uint8_t laser_ocr(float s) {
    if (s <= 0.0f) return 0;
    if (s >= settings.max_spindle) return 255;
    return (uint8_t)(s * 255.0f / settings.max_spindle);
}

// The rate of a move of `d_mm` along the axes: `rate` held so that no axis exceeds its $110/$111.
static float limited_rate(float rate, const float d_mm[2], float length_mm) {
    for (uint8_t a = 0; a < 2; ++a) {
        if (d_mm[a] == 0.0f) continue;
        const float axis_limit = settings.max_rate_mm_min[a] * length_mm / fabsf(d_mm[a]);
        if (rate > axis_limit) rate = axis_limit;
    }
    return rate;
}

static void queue_move(const float target_mm[2]) {
    int32_t d[2];
    float d_mm[2];
    for (uint8_t a = 0; a < 2; ++a) {
        const int32_t target = lroundf(target_mm[a] * settings.steps_per_mm[a]);
        d[a] = target - planned_steps[a];
        planned_steps[a] = target;
        d_mm[a] = (float)d[a] / settings.steps_per_mm[a];
    }
    const uint32_t events = (uint32_t)(labs(d[0]) > labs(d[1]) ? labs(d[0]) : labs(d[1]));
    if (events == 0) return;
    const float length_mm = sqrtf(d_mm[0] * d_mm[0] + d_mm[1] * d_mm[1]);
    const float rate = limited_rate(motion_mode == 0 ? 1e9f : gcode_feed_mm_min, d_mm, length_mm);
    const float events_per_s = rate / 60.0f * (float)events / length_mm;
    uint32_t cycles = (uint32_t)((float)F_CPU / events_per_s + 0.5f);
    if (cycles < MIN_STEP_CYCLES) cycles = MIN_STEP_CYCLES;
    const uint8_t power = laser_on && (!settings.laser_mode || motion_mode == 1) ? laser_ocr(gcode_power) : 0;
    motion_queue(d[0], d[1], cycles, power);
}

uint8_t gcode_execute(const char* line) {
    float target_mm[2] = {(float)planned_steps[0] / settings.steps_per_mm[0],
                          (float)planned_steps[1] / settings.steps_per_mm[1]};
    uint8_t axis_words = 0;
    uint8_t mode = motion_mode;
    int8_t laser = -1;
    float feed = gcode_feed_mm_min;
    float power = gcode_power;
    while (*line != '\0') {
        const char letter = *line++;
        if (letter < 'A' || letter > 'Z') return STATUS_EXPECTED_COMMAND_LETTER;
        char* end = 0;
        const float value = (float)strtod(line, &end);
        if (end == line) return STATUS_BAD_NUMBER_FORMAT;
        line = end;
        const int16_t code = (int16_t)value;
        switch (letter) {
            case 'G':
                if (value != (float)code) return STATUS_UNSUPPORTED_COMMAND;
                if (code == 0 || code == 1) mode = (uint8_t)code;
                else if (code != 17 && code != 21 && code != 90 && code != 94) return STATUS_UNSUPPORTED_COMMAND;
                break;
            case 'M':
                if (code == 3 || code == 4) laser = 1;
                else if (code == 5 || code == 2 || code == 30) laser = 0;
                else return STATUS_UNSUPPORTED_COMMAND;
                break;
            case 'X': target_mm[0] = value; axis_words |= 1; break;
            case 'Y': target_mm[1] = value; axis_words |= 2; break;
            case 'F':
                if (value < 0.0f) return STATUS_NEGATIVE_VALUE;
                feed = value;
                break;
            case 'S':
                if (value < 0.0f) return STATUS_NEGATIVE_VALUE;
                power = value;
                break;
            case 'N': break;
            default: return STATUS_UNSUPPORTED_COMMAND;
        }
    }
    if (axis_words != 0 && mode == 1 && feed <= 0.0f) return STATUS_UNDEFINED_FEED_RATE;
    motion_mode = mode;
    gcode_feed_mm_min = feed;
    gcode_power = power;
    if (laser >= 0) laser_on = (uint8_t)laser;
    // Outside laser mode the laser follows M3/M5 at once; in laser mode it is on only while a G1 runs.
    motion_laser(laser_on && !settings.laser_mode ? laser_ocr(gcode_power) : 0);
    if (axis_words != 0) queue_move(target_mm);
    return STATUS_OK;
}
