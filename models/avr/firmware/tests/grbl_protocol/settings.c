#include "settings.h"

#include <stdlib.h>

#include "report.h"
#include "serial.h"
#include "status.h"

Settings settings;

// grbl 1.1 defaults.h (DEFAULTS_GENERIC): $0 = 10, $1 = 25, $30 = 1000, $32 = 0, 250 steps/mm, 500 mm/min, 10 mm/s^2.
void settings_init(void) {
    settings.pulse_us = 10;
    settings.idle_delay_ms = 25;
    settings.max_spindle = 1000.0f;
    settings.laser_mode = 0;
    for (uint8_t a = 0; a < 2; ++a) {
        settings.steps_per_mm[a] = 250.0f;
        settings.max_rate_mm_min[a] = 500.0f;
        settings.accel_mm_s2[a] = 10.0f;
    }
}

static uint8_t read_uint(const char** text, uint16_t* out) {
    const char* c = *text;
    if (*c < '0' || *c > '9') return 0;
    uint16_t v = 0;
    while (*c >= '0' && *c <= '9') v = (uint16_t)(v * 10 + (uint16_t)(*c++ - '0'));
    *text = c;
    *out = v;
    return 1;
}

uint8_t settings_store(const char* text) {
    uint16_t n = 0;
    if (!read_uint(&text, &n) || *text != '=') return STATUS_INVALID_STATEMENT;
    ++text;
    char* end = 0;
    const float v = (float)strtod(text, &end);
    if (end == text || *end != '\0') return STATUS_BAD_NUMBER_FORMAT;
    if (v < 0.0f) return STATUS_NEGATIVE_VALUE;
    switch (n) {
        case 0: settings.pulse_us = (uint8_t)v; break;
        case 1: settings.idle_delay_ms = (uint8_t)v; break;
        case 30: settings.max_spindle = v; break;
        case 32: settings.laser_mode = v != 0.0f; break;
        case 100: settings.steps_per_mm[0] = v; break;
        case 101: settings.steps_per_mm[1] = v; break;
        case 110: settings.max_rate_mm_min[0] = v; break;
        case 111: settings.max_rate_mm_min[1] = v; break;
        case 120: settings.accel_mm_s2[0] = v; break;
        case 121: settings.accel_mm_s2[1] = v; break;
        default: return STATUS_INVALID_STATEMENT;
    }
    return STATUS_OK;
}

static void report_setting(uint16_t n, float v) {
    serial_write('$');
    report_uint(n);
    serial_write('=');
    report_float(v);
    serial_print("\r\n");
}

void settings_report(void) {
    report_setting(0, settings.pulse_us);
    report_setting(1, settings.idle_delay_ms);
    report_setting(30, settings.max_spindle);
    report_setting(32, settings.laser_mode);
    for (uint8_t a = 0; a < 2; ++a) report_setting(100 + a, settings.steps_per_mm[a]);
    for (uint8_t a = 0; a < 2; ++a) report_setting(110 + a, settings.max_rate_mm_min[a]);
    for (uint8_t a = 0; a < 2; ++a) report_setting(120 + a, settings.accel_mm_s2[a]);
}
