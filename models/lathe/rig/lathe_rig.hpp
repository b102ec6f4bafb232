// Seed 002's lathe at chip level (no SystemC): the ATmega16 model running the lathe_sync firmware, the L298 and
// the derived motor with the drive train, the motor encoder and the spindle encoder + index through the 74HC14
// inverters, the 4x4 keypad matrix an operator presses, and an HD44780 that is always ready. Stepped 1 us at a
// time: the plant reads EN/DIR at each step and encoder edges land on the step (the PID ticks and the spindle
// pulses are hundreds of us apart). It records what the lathe metrics need (docs/metrics.md "Lathe"): the
// carriage at each spindle pulse of each pass (the time the firmware's PID runs), the motor pulses, the time the
// PID output sits at a clamp, and the carriage's overshoot after each brake.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "avr/avr_chip.hpp"
#include "lathe/core/dc_motor.hpp"
#include "lathe/core/drive_train.hpp"
#include "lathe/core/keypad.hpp"
#include "lathe/core/thread_metrics.hpp"

namespace cnc::lathe {

inline constexpr int kSpindleSlots = 40;  // spindle encoder disc: SP_PPR pulses per revolution (seed 002 §6.1)

struct LatheRigConfig {
    std::string firmware_elf;
    double spindle_rpm = 0.0;
    DcMotorParams motor = derive_motor();
    DriveTrainParams train;
};

// One cutting pass as recorded: the carriage along the cut at its start and at each spindle pulse, the motor
// pulses (falling edges at the MCU, as INT0 sees them) at the same instants.
struct RecordedPass {
    ThreadPass thread;
    std::vector<long> motor_pulses;
    double start_s = 0.0;
    double pid_s = 0.0;          // time the PID ran
    double at_full_s = 0.0;      // of which OCR1A = 1023 (the clamp PWM_TOP)
    double at_zero_s = 0.0;      // of which OCR1A = 0
    double overshoot_mm = -1.0;  // carriage travel from the PID stop to 0.6 s later (the 500 ms brake done)
};

class LatheRig {
public:
    explicit LatheRig(const LatheRigConfig& cfg);
    virtual ~LatheRig() = default;
    LatheRig(const LatheRig&) = delete;
    LatheRig& operator=(const LatheRig&) = delete;

    void step();  // 1 us
    void run_for(double s);
    // The operator presses a key for 100 ms and lets it go for 400 ms (read_key's 200 ms debounce in between).
    void press(char key);
    void type(const std::string& keys);
    // Holds `key` for `s` (a key held at power-up: B = tuning mode, D = configuration, §6.6).
    void hold(char key, double s);

    [[nodiscard]] double now_s() const;
    [[nodiscard]] double spindle_rev() const;
    [[nodiscard]] bool pid_running() const;

    avr::AvrChip chip;
    DcMotor motor;
    DriveTrain train;
    std::vector<KeyPos> pressed;
    std::vector<RecordedPass> passes;
    long motor_pulses = 0;

private:
    [[nodiscard]] bool motor_encoder_level() const;
    void update_spindle(bool force);
    void update_keypad();
    void record(double dt_s);  // the step just run, s

    double m_spindle_rev_per_s;
    avr::Cycle m_last = 0;
    bool m_motor_level = true;
    bool m_spindle_level = true;
    bool m_index = true;
    bool m_was_running = false;
    std::array<int, 4> m_row_level{-1, -1, -1, -1};  // the rows as last driven (-1: not yet)
    double m_cut_sign = 1.0;
    double m_brake_from_mm = 0.0;
    double m_brake_until_s = -1.0;
};

}  // namespace cnc::lathe
