#include "lathe/rig/lathe_rig.hpp"

#include <cmath>

namespace cnc::lathe {

namespace {

using avr::Cycle;
using avr::Pin;

constexpr double kPi = 3.14159265358979323846;
constexpr double kFcpuHz = 8e6;  // seed 002 §6.1 F_CPU
constexpr double kCycleS = 1.0 / kFcpuHz;
constexpr Cycle kStepCycles = 8;  // 1 us

avr::AvrCoreConfig firmware(const std::string& elf) {
    avr::AvrCoreConfig cfg;
    cfg.firmware_elf = elf;
    cfg.mcu = "atmega16";
    cfg.f_cpu_hz = 8'000'000;
    return cfg;
}

}  // namespace

LatheRig::LatheRig(const LatheRigConfig& cfg)
    : chip(firmware(cfg.firmware_elf)), motor(cfg.motor), train(cfg.train),
      m_spindle_rev_per_s(cfg.spindle_rpm / 60.0) {
    chip.drive_input(Pin{'A', 3}, false);  // the LCD's busy flag (D7) always reads ready
    chip.drive_input(Pin{'D', 7}, true);   // limit switch closed (normally 1)
    m_motor_level = motor_encoder_level();
    chip.drive_input(Pin{'D', 2}, m_motor_level);
    update_spindle(true);
}

double LatheRig::now_s() const { return static_cast<double>(chip.cycle()) * kCycleS; }

double LatheRig::spindle_rev() const { return m_spindle_rev_per_s * now_s(); }

bool LatheRig::pid_running() const { return chip.timer(0).divisor() != 0; }

// The 74HC14 inverts the slotted opto's output: the MCU sees a falling edge when a slot's start passes. The motor
// disc starts half a slot past one.
bool LatheRig::motor_encoder_level() const {
    const double slots = motor.state().angle_rad * kMotorSlots / (2 * kPi) + 0.5;
    return slots - std::floor(slots) < 0.5;
}

// Spindle: kSpindleSlots = 40 slots (falling edge at each 1/40 rev) and the half-reflective index disc, high for half a
// revolution: its falling edge is at 1/2 + 1/80 rev, halfway between two slot edges. Were it on a slot edge,
// whether the INT1 ISR of that slot runs before or after doCut's `Error = slip` would be left to the cycle the two
// edges happen to land on, and one pass would carry a whole B(n) (6 or 7 pulses at 1 mm) more than another.
void LatheRig::update_spindle(bool force) {
    const double rev = spindle_rev();
    const double slots = rev * kSpindleSlots;
    const bool slot_level = slots - std::floor(slots) < 0.5;
    const double index_rev = rev - 0.5 / kSpindleSlots;
    const bool index_level = index_rev - std::floor(index_rev) < 0.5;
    if (force || slot_level != m_spindle_level) chip.drive_input(Pin{'D', 3}, slot_level);
    if (force || index_level != m_index) chip.drive_input(Pin{'D', 6}, index_level);
    if (!force && m_spindle_level && !slot_level && pid_running() && !passes.empty()) {
        passes.back().thread.x_mm.push_back(m_cut_sign * train.carriage_mm());
        passes.back().motor_pulses.push_back(motor_pulses);
    }
    m_spindle_level = slot_level;
    m_index = index_level;
}

// Rows read low where a pressed key's column is driven low.
void LatheRig::update_keypad() {
    for (int row = 0; row < 4; ++row) {
        bool low = false;
        for (const KeyPos& k : pressed) {
            if (k.row == row && !chip.pin_level(Pin{'B', 7 - k.col})) low = true;
        }
        auto& level = m_row_level[static_cast<std::size_t>(row)];
        if (level != static_cast<int>(!low)) chip.drive_input(Pin{'B', 3 - row}, !low);
        level = !low;
    }
}

// A pass starts when doCut starts the PID (at the spindle index) and ends when it stops it before the brake.
void LatheRig::record(double dt_s) {
    const bool running = pid_running();
    if (running && !m_was_running) {
        if (passes.empty()) m_cut_sign = chip.pin_level(Pin{'D', 0}) ? 1.0 : -1.0;  // DIR1 high: positive volts
        passes.emplace_back();
        passes.back().start_s = now_s();
        passes.back().thread.x_mm.push_back(m_cut_sign * train.carriage_mm());
        passes.back().motor_pulses.push_back(motor_pulses);
    }
    if (running) {
        RecordedPass& p = passes.back();
        const std::uint16_t duty = chip.timer(1).ocr(avr::Channel::A);
        p.pid_s += dt_s;
        if (duty >= 1023) p.at_full_s += dt_s;
        if (duty == 0) p.at_zero_s += dt_s;
    }
    if (!running && m_was_running) {
        m_brake_from_mm = train.carriage_mm();
        m_brake_until_s = now_s() + 0.6;
    }
    if (m_brake_until_s >= 0.0 && now_s() >= m_brake_until_s) {
        passes.back().overshoot_mm = std::abs(train.carriage_mm() - m_brake_from_mm);
        m_brake_until_s = -1.0;
    }
    m_was_running = running;
}

void LatheRig::step() {
    const Cycle to = chip.cycle() + kStepCycles;
    const double dt = static_cast<double>(to - m_last) * kCycleS;
    m_last = to;
    const bool en = chip.pin_level(Pin{'D', 5});
    const bool dir1 = chip.pin_level(Pin{'D', 0});
    const bool dir2 = chip.pin_level(Pin{'D', 1});
    const BridgeMode mode = !en ? BridgeMode::Coast : dir1 != dir2 ? BridgeMode::Drive : BridgeMode::Brake;
    motor.advance(dt, mode, dir1 ? kBridgeVolts : -kBridgeVolts, 0.0);
    train.follow(motor.state().angle_rad);
    chip.run_until(to);
    const bool level = motor_encoder_level();
    if (level != m_motor_level) chip.drive_input(Pin{'D', 2}, level);
    if (m_motor_level && !level) ++motor_pulses;
    m_motor_level = level;
    record(dt);
    update_spindle(false);
    update_keypad();
}

void LatheRig::run_for(double s) {
    const Cycle end = chip.cycle() + static_cast<Cycle>(s * kFcpuHz);
    while (chip.cycle() < end) step();
}

void LatheRig::press(char key) {
    hold(key, 0.1);
    run_for(0.4);
}

void LatheRig::type(const std::string& keys) {
    for (const char k : keys) press(k);
}

void LatheRig::hold(char key, double s) {
    pressed = {key_pos(key)};
    run_for(s);
    pressed.clear();
}

}  // namespace cnc::lathe
