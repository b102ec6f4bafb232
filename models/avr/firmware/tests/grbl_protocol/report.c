#include "report.h"

#include "motion.h"
#include "serial.h"
#include "settings.h"

extern float gcode_feed_mm_min;  // gcode.c: the feed and laser power in force, for the status report
extern float gcode_power;

void report_uint(uint32_t value) {
    char digits[10];
    uint8_t n = 0;
    do {
        digits[n++] = (char)('0' + value % 10);
        value /= 10;
    } while (value != 0);
    while (n != 0) serial_write((uint8_t)digits[--n]);
}

void report_float(float value) {
    if (value < 0.0f) {
        serial_write('-');
        value = -value;
    }
    const uint32_t thousandths = (uint32_t)(value * 1000.0f + 0.5f);
    report_uint(thousandths / 1000);
    serial_write('.');
    const uint16_t frac = (uint16_t)(thousandths % 1000);
    serial_write((uint8_t)('0' + frac / 100));
    serial_write((uint8_t)('0' + frac / 10 % 10));
    serial_write((uint8_t)('0' + frac % 10));
}

void report_status_message(uint8_t status) {
    if (status == 0) {
        serial_print("ok\r\n");
        return;
    }
    serial_print("error:");
    report_uint(status);
    serial_print("\r\n");
}

void report_realtime_status(void) {
    int32_t steps[2];
    motion_position(steps);
    serial_print(motion_idle() ? "<Idle|MPos:" : "<Run|MPos:");
    for (uint8_t a = 0; a < 2; ++a) {
        report_float((float)steps[a] / settings.steps_per_mm[a]);
        serial_write(',');
    }
    serial_print("0.000|FS:");
    report_uint((uint32_t)gcode_feed_mm_min);
    serial_write(',');
    report_uint((uint32_t)gcode_power);
    serial_print(">\r\n");
}
