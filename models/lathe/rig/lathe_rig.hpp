// Seed 002's lathe at chip level (no SystemC): the ATmega16 model running the lathe_sync firmware wired to one
// block per part (models/lathe/core): the L298, the derived motor with the drive train, the motor encoder and the
// spindle encoder + index through the 74HC14 inverters, the spindle with its cutting load, the 4x4 keypad matrix
// an operator presses and the HD44780 with the transcript of what it shows. It records what the lathe metrics
// need (docs/metrics.md "Lathe"): the carriage at each spindle pulse of each pass (the time the firmware's PID
// runs), the motor pulses, the time the PID output sits at a clamp, and the carriage's overshoot after each brake.
//
// Lock-stepped, 1 us at a time, instead of SystemC modules around the AVR core: the plant reads EN/DIR after
// each step and its encoder edges land on the step's cycle, so INT0/INT1 see every edge at most 1 us (8 cycles)
// late whatever the AVR core does. A SystemC AvrCore runs the CPU ahead in quanta (160 cycles) and sees an input
// only at a quantum's end, so it would deliver these edges up to 20 us late, or need a quantum of 8 cycles and a
// context switch per microsecond; the PID ticks and the spindle pulses are hundreds of us apart, so 1 us is exact
// enough and the loop stays a plain function call (docs/architectures.md "lathe-sync"). The LCD's E pulse (500
// ns) is shorter than the step: the HD44780 and the pin trace read the pins in the chip's output-change callback,
// at their own cycle; the keypad columns, held 1 ms per scan step, are read after each step.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "avr/avr_chip.hpp"
#include "common/tool_sample.hpp"
#include "lathe/core/dc_motor.hpp"
#include "lathe/core/drive_train.hpp"
#include "lathe/core/hd44780.hpp"
#include "lathe/core/keypad.hpp"
#include "lathe/core/l298.hpp"
#include "lathe/core/lcd_transcript.hpp"
#include "lathe/core/slotted_encoder.hpp"
#include "lathe/core/spindle.hpp"
#include "lathe/core/thread_metrics.hpp"

namespace cnc::lathe {

inline constexpr int kSpindleSlots = 40;  // spindle encoder disc: SP_PPR pulses per revolution (seed 002 §2.5.3)
// The operator's key press (LatheRig::press): held long enough for read_key's 4 ms scan, then let go past its
// 200 ms debounce (seed 002 §2.5.3).
inline constexpr double kKeyHeldS = 0.1;
inline constexpr double kKeyReleasedS = 0.4;

struct LatheRigConfig {
    std::string firmware_elf;
    double spindle_rpm = 0.0;
    DcMotorParams motor = derive_motor();
    DriveTrainParams train;
    SpindleParams spindle;  // its rpm is spindle_rpm
    CutParams cut;          // depth 0: no cutting load
    double feed_mm_per_rev = 0.0;
    bool trace_pins = false;  // record the pin edges (LatheRig::trace)
    // Record the carriage at each motor and spindle encoder edge (LatheRig::carriage_samples): an independent
    // reading of the thread beside the pins (cncsim run --samples).
    bool record_carriage = false;
    ClockDeviation clock;  // how the board's 8 MHz oscillator departs from F_CPU (all zero: ideal)
    bool fast_forward = true;  // AvrCoreConfig::fast_forward
};

// One cutting pass as recorded: the carriage along the cut at its start and at each spindle pulse, the motor
// pulses (falling edges at the MCU, as INT0 sees them) at the same instants.
struct RecordedPass {
    ThreadPass thread;
    std::vector<long> motor_pulses;
    double start_s = 0.0;
    double pid_s = 0.0;            // time the PID ran
    double at_full_s = 0.0;        // of which OCR1A = 1023 (the clamp PWM_TOP)
    double at_zero_s = 0.0;        // of which OCR1A = 0
    double overshoot_mm = -1.0;    // carriage travel from the PID stop to 0.6 s later (the 500 ms brake done)
    double spindle_min_rpm = 0.0;  // the slowest the spindle turned under the cut
};

// The MCU pins the rig traces, with their signal names (LatheRig::trace) and the part wired to each (the L298, an
// encoder, the keypad, the LCD: the VCD's scopes).
struct TracedPin {
    const char* name;
    avr::Pin pin;
    const char* block;
};
[[nodiscard]] const std::vector<TracedPin>& traced_pins();

struct PinEdge {
    avr::Cycle cycle;
    std::uint16_t pin;  // index in traced_pins()
    bool level;
};

class LatheRig {
public:
    explicit LatheRig(const LatheRigConfig& cfg);
    virtual ~LatheRig() = default;
    LatheRig(const LatheRig&) = delete;
    LatheRig& operator=(const LatheRig&) = delete;

    void step();  // 1 us
    void run_for(double s);
    // `f` is called with the simulated time each time run_for has run another `every_s` (the progress display).
    void on_slice(double every_s, std::function<void(double now_s)> f);
    // The operator presses a key for kKeyHeldS and lets it go for kKeyReleasedS.
    void press(char key);
    void type(const std::string& keys);
    // Holds `key` for `s` (a key held at power-up: B = tuning mode, D = configuration, §2.5.3).
    void hold(char key, double s);

    [[nodiscard]] double now_s() const;
    // The time of a cycle of the ATmega16's clock, s.
    [[nodiscard]] double cycle_s(avr::Cycle c) const;
    [[nodiscard]] bool pid_running() const;
    // The screens the LCD settled on so far.
    [[nodiscard]] const std::vector<LcdScreen>& lcd_screens() { return m_transcript.screens(now_s()); }
    // The traced pins' levels at the start and their edges in time order (LatheRigConfig::trace_pins).
    [[nodiscard]] const std::vector<bool>& trace_initial() const { return m_trace_initial; }
    [[nodiscard]] const std::vector<PinEdge>& trace() const { return m_trace; }

    avr::AvrChip chip;
    L298 bridge;
    DcMotor motor;
    DriveTrain train;
    SlottedEncoder motor_encoder;
    SlottedEncoder spindle_encoder;
    SlottedEncoder spindle_index;
    Spindle spindle;
    KeypadMatrix keypad;
    Hd44780 lcd;
    std::vector<RecordedPass> passes;
    long motor_pulses = 0;
    // The carriage (x: mm from power-up, positive with DIR1 high) at each motor and spindle encoder edge, at the
    // edge's cycle (LatheRigConfig::record_carriage).
    std::vector<ToolSample> carriage_samples;

private:
    void outputs_changed(avr::Cycle c);
    void update_spindle(bool force);
    void update_keypad();
    void record(double dt_s);  // the step just run, s
    void drive(const avr::Pin& pin, bool level);
    void sample_carriage();

    double m_cut_torque_nm;
    LcdTranscript m_transcript;
    avr::Cycle m_last = 0;
    double m_cycle_period_s = 0.0;  // 1 / the clock's whole hertz
    bool m_motor_level = true;
    bool m_spindle_level = true;
    bool m_index = true;
    bool m_was_running = false;
    bool m_lcd_e = false;
    std::array<int, 4> m_row_level{-1, -1, -1, -1};  // the rows as last driven (-1: not yet)
    double m_cut_sign = 1.0;
    double m_brake_from_mm = 0.0;
    double m_brake_until_s = -1.0;
    avr::Cycle m_slice_cycles = 0;
    avr::Cycle m_next_slice = 0;
    std::function<void(double)> m_on_slice;
    bool m_record_carriage;
    bool m_trace_on = false;
    std::vector<bool> m_trace_initial;
    std::vector<bool> m_trace_level;
    std::vector<PinEdge> m_trace;
};

}  // namespace cnc::lathe
