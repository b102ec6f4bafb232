// A chip-level bench for seed 002's lathe (no SystemC): the ATmega16 model running the lathe_sync firmware, the
// L298 and derived motor with the drive train, the motor encoder and the spindle encoder + index through the
// 74HC14 inverters, a keypad matrix an operator presses, and an LCD that is always ready. Stepped 1 us at a time:
// the plant reads EN/DIR at each step and encoder edges land on the step (the PID and the spindle pulses are
// hundreds of us apart). The lathe-sync architecture's SystemC system is to replace it (issue 12).
#pragma once
#include <cmath>
#include <optional>
#include <vector>

#include "avr/avr_chip.hpp"
#include "lathe/core/dc_motor.hpp"
#include "lathe/core/drive_train.hpp"

namespace cnc::lathe::test {

using avr::Cycle;
using avr::Pin;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kCycleS = 1.0 / 8e6;
inline constexpr Cycle kStepCycles = 8;  // 1 us

inline avr::AvrCoreConfig lathe_firmware(const char* elf) {
    avr::AvrCoreConfig cfg;
    cfg.firmware_elf = elf;
    cfg.mcu = "atmega16";
    cfg.f_cpu_hz = 8'000'000;
    return cfg;
}

// Keys by (column 0..3 = PB7..PB4, row 0..3 = PB3..PB0), seed 002 §6.6.
struct KeyPos {
    int col;
    int row;
};
inline KeyPos key_pos(char key) {
    switch (key) {
        case '1': return {0, 0};
        case '4': return {0, 1};
        case '7': return {0, 2};
        case '*': return {0, 3};
        case '2': return {1, 0};
        case '5': return {1, 1};
        case '8': return {1, 2};
        case '0': return {1, 3};
        case '3': return {2, 0};
        case '6': return {2, 1};
        case '9': return {2, 2};
        case '#': return {2, 3};
        case 'A': return {3, 0};
        case 'B': return {3, 1};
        case 'C': return {3, 2};
        default: return {3, 3};  // 'D'
    }
}

struct LatheBench {
    explicit LatheBench(double spindle_rpm = 0.0, const char* elf = LATHE_SYNC_ELF)
        : chip(lathe_firmware(elf)), motor(derive_motor()), train({}), spindle_rev_per_s(spindle_rpm / 60.0) {
        chip.drive_input(Pin{'A', 3}, false);  // the LCD's busy flag (D7) always reads ready
        chip.drive_input(Pin{'D', 7}, true);   // limit switch closed (normally 1)
        motor_level = motor_encoder_level();
        chip.drive_input(Pin{'D', 2}, motor_level);
        update_spindle(true);
    }

    // The 74HC14 inverts the slotted opto's output: the MCU sees a falling edge when a slot's start passes. The
    // motor disc starts half a slot past one.
    [[nodiscard]] bool motor_encoder_level() const {
        const double slots = motor.state().angle_rad * 30.0 / (2 * kPi) + 0.5;
        return slots - std::floor(slots) < 0.5;
    }

    [[nodiscard]] double spindle_rev() const { return spindle_rev_per_s * static_cast<double>(chip.cycle()) * kCycleS; }

    // Spindle: 40 slots (falling edge at each 1/40 rev) and the half-reflective index disc, high for half a
    // revolution: its falling edge is at 1/2 + 1/80 rev, halfway between two slot edges. Were it on a slot edge,
    // whether the INT1 ISR of that slot runs before or after doCut's `Error = slip` would be left to the cycle
    // the two edges happen to land on, and one pass would carry a whole B(n) (6 or 7 pulses at 1 mm) more than
    // another.
    void update_spindle(bool force = false) {
        const double rev = spindle_rev();
        const double slots = rev * 40.0;
        const bool slot_level = slots - std::floor(slots) < 0.5;
        const double index_rev = rev - 1.0 / 80.0;
        const bool index_level = index_rev - std::floor(index_rev) < 0.5;
        if (force || slot_level != spindle_level) chip.drive_input(Pin{'D', 3}, slot_level);
        if (force || index_level != index) chip.drive_input(Pin{'D', 6}, index_level);
        if (!force && spindle_level && !slot_level) on_spindle_pulse();
        spindle_level = slot_level;
        index = index_level;
    }

    virtual void on_spindle_pulse() {}
    virtual ~LatheBench() = default;

    // Rows read low where a pressed key's column is driven low.
    void update_keypad() {
        for (int row = 0; row < 4; ++row) {
            bool low = false;
            for (const KeyPos& k : pressed) {
                if (k.row == row && !chip.pin_level(Pin{'B', 7 - k.col})) low = true;
            }
            chip.drive_input(Pin{'B', 3 - row}, !low);
        }
    }

    void step() {
        const Cycle to = chip.cycle() + kStepCycles;
        const double dt = static_cast<double>(to - last) * kCycleS;
        last = to;
        const bool en = chip.pin_level(Pin{'D', 5});
        const bool dir1 = chip.pin_level(Pin{'D', 0});
        const bool dir2 = chip.pin_level(Pin{'D', 1});
        const BridgeMode mode = !en ? BridgeMode::Coast : dir1 != dir2 ? BridgeMode::Drive : BridgeMode::Brake;
        motor.advance(dt, mode, dir1 ? 22.0 : -22.0, 0.0);
        train.follow(motor.state().angle_rad);
        chip.run_until(to);
        const bool level = motor_encoder_level();
        if (level != motor_level) chip.drive_input(Pin{'D', 2}, level);
        motor_level = level;
        update_spindle();
        update_keypad();
    }

    void run_for(double s) {
        const Cycle end = chip.cycle() + static_cast<Cycle>(s * 8e6);
        while (chip.cycle() < end) step();
    }

    // The operator presses a key for 100 ms and lets it go for 400 ms (read_key's 200 ms debounce in between).
    void press(char key) {
        pressed.push_back(key_pos(key));
        run_for(0.1);
        pressed.clear();
        run_for(0.4);
    }
    void type(const char* keys) {
        for (const char* k = keys; *k; ++k) press(*k);
    }

    avr::AvrChip chip;
    DcMotor motor;
    DriveTrain train;
    double spindle_rev_per_s = 0.0;
    std::vector<KeyPos> pressed;
    Cycle last = 0;
    bool motor_level = true;
    bool spindle_level = true;
    bool index = true;
};

}  // namespace cnc::lathe::test
