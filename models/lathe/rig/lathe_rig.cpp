#include "lathe/rig/lathe_rig.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace cnc::lathe {

namespace {

using avr::Cycle;
using avr::Pin;

constexpr double kPi = 3.14159265358979323846;
constexpr double kFcpuHz = 8e6;   // seed 002 §2.5.3 F_CPU
constexpr Cycle kStepCycles = 8;  // 1 us at F_CPU

// Seed 002's pin map (the §2.5.3 listing).
constexpr Pin kEnA{'D', 5};  // OC1A
constexpr Pin kDir1{'D', 0};
constexpr Pin kDir2{'D', 1};
constexpr Pin kMotorPulse{'D', 2};    // INT0
constexpr Pin kSpindlePulse{'D', 3};  // INT1
constexpr Pin kIndex{'D', 6};
constexpr Pin kLimit{'D', 7};
constexpr Pin kLcdD7{'A', 3};  // D4..D7 = PA0..PA3
constexpr Pin kLcdRs{'A', 4};
constexpr Pin kLcdRw{'A', 5};
constexpr Pin kLcdE{'A', 6};

avr::AvrCoreConfig firmware(const LatheRigConfig& rig) {
    avr::AvrCoreConfig cfg;
    cfg.firmware_elf = rig.firmware_elf;
    cfg.mcu = "atmega16";
    cfg.f_cpu_hz = 8'000'000;
    cfg.clock = rig.clock;
    cfg.fast_forward = rig.fast_forward;
    return cfg;
}

SpindleParams spindle_at(const LatheRigConfig& cfg) {
    SpindleParams p = cfg.spindle;
    p.rpm = cfg.spindle_rpm;
    return p;
}

}  // namespace

const std::vector<TracedPin>& traced_pins() {
    // Grouped by the part at each pin's other end (docs/architectures.md, "lathe-sync": the chain).
    static const std::vector<TracedPin> pins = {{"oc1a_ena_pd5", kEnA, "l298"},
                                                {"dir1_in1_pd0", kDir1, "l298"},
                                                {"dir2_in2_pd1", kDir2, "l298"},
                                                {"int0_motor_pd2", kMotorPulse, "motor_encoder"},
                                                {"int1_spindle_pd3", kSpindlePulse, "spindle_encoder"},
                                                {"index_pd6", kIndex, "spindle_encoder"},
                                                {"limit_pd7", kLimit, "limit_switch"},
                                                {"col1_pb7", {'B', 7}, "keypad"},
                                                {"col2_pb6", {'B', 6}, "keypad"},
                                                {"col3_pb5", {'B', 5}, "keypad"},
                                                {"col4_pb4", {'B', 4}, "keypad"},
                                                {"row1_pb3", {'B', 3}, "keypad"},
                                                {"row2_pb2", {'B', 2}, "keypad"},
                                                {"row3_pb1", {'B', 1}, "keypad"},
                                                {"row4_pb0", {'B', 0}, "keypad"},
                                                {"lcd_rs_pa4", kLcdRs, "lcd"},
                                                {"lcd_rw_pa5", kLcdRw, "lcd"},
                                                {"lcd_e_pa6", kLcdE, "lcd"},
                                                {"lcd_d4_pa0", {'A', 0}, "lcd"},
                                                {"lcd_d5_pa1", {'A', 1}, "lcd"},
                                                {"lcd_d6_pa2", {'A', 2}, "lcd"},
                                                {"lcd_d7_pa3", kLcdD7, "lcd"}};
    return pins;
}

// The motor disc starts at a fall (half a pitch past a leading edge). The spindle's 40 slots fall at (k + 1/2) / 40
// rev and its index at 1/2 + 1/80 rev: on slot 20's fall, so the firmware sees that slot's INT1 edge and the
// index fall doCut waits for in the same 1 us step at every pass. Moved off the slot fall (by a
// quarter, a half or three quarters of a slot pitch), the index leaves the first pass as it is, but passes 2 and 3
// (which start from the retract's slip) swing into a limit cycle with following errors of 60 to 160 pulses
// instead of 2. The thesis does not say where its index sits relative to the slots (docs/metrics.md "Lathe").
LatheRig::LatheRig(const LatheRigConfig& cfg)
    : chip(firmware(cfg)),
      motor(cfg.motor),
      train(cfg.train),
      motor_encoder(kMotorSlots, 0.5),
      spindle_encoder(kSpindleSlots, 0.0),
      spindle_index(1.0, -0.5 / kSpindleSlots),
      spindle(spindle_at(cfg)),
      m_cut_torque_nm(cutting_torque_nm(cfg.cut, cfg.feed_mm_per_rev)),
      m_record_carriage(cfg.record_carriage) {
    m_cycle_period_s = 1.0 / static_cast<double>(chip.clock().hz());
    chip.on_output_change([this](Cycle c) { outputs_changed(c); });
    drive(kLcdD7, false);  // the LCD's busy flag (D7) always reads ready
    drive(kLimit, true);   // limit switch closed (normally 1)
    m_motor_level = motor_encoder.y_at(0.0);
    drive(kMotorPulse, m_motor_level);
    update_spindle(true);
    if (cfg.trace_pins) {
        for (const TracedPin& p : traced_pins()) m_trace_initial.push_back(chip.pin_level(p.pin));
        m_trace_level = m_trace_initial;
        m_trace_on = true;
    }
}

double LatheRig::now_s() const {
    return cycle_s(chip.cycle());
}

// A cycle's time as the clock's whole cycles plus its edge's jitter: the cycles' part is the same double as the
// nominal clock's c x (1 / F_CPU), so the ideal clock reproduces the seed's timing to the last bit.
double LatheRig::cycle_s(Cycle c) const {
    return static_cast<double>(c) * m_cycle_period_s + ps_to_s(chip.clock().jitter_ps(c));
}

bool LatheRig::pid_running() const {
    return chip.timer(0).divisor() != 0;
}

void LatheRig::sample_carriage() {
    if (!m_record_carriage) return;
    carriage_samples.push_back({chip.clock().at(chip.cycle()), {train.carriage_mm(), 0.0}});
}

void LatheRig::drive(const Pin& pin, bool level) {
    chip.drive_input(pin, level);
    outputs_changed(chip.cycle());
}

// The HD44780 latches on E's fall (3 cycles after its rise), and the trace wants every edge at its cycle.
void LatheRig::outputs_changed(Cycle c) {
    const bool e = chip.pin_level(kLcdE);
    if (e != m_lcd_e) {
        m_lcd_e = e;
        std::uint8_t data = 0;
        for (int bit = 0; bit < 4; ++bit) data |= static_cast<std::uint8_t>(chip.pin_level(Pin{'A', bit}) << bit);
        const std::uint64_t before = lcd.changes();
        lcd.pins(chip.pin_level(kLcdRs), chip.pin_level(kLcdRw), e, data);
        if (lcd.changes() != before) m_transcript.changed(cycle_s(c), lcd.lines());
    }
    if (!m_trace_on) return;
    const std::vector<TracedPin>& pins = traced_pins();
    for (std::size_t i = 0; i < pins.size(); ++i) {
        const bool level = chip.pin_level(pins[i].pin);
        if (level == m_trace_level[i]) continue;
        m_trace_level[i] = level;
        m_trace.push_back({c, static_cast<std::uint16_t>(i), level});
    }
}

void LatheRig::update_spindle(bool force) {
    const double rev = spindle.rev();
    const bool slot_level = spindle_encoder.y_at(rev);
    const bool index_level = spindle_index.y_at(rev);
    if (force || slot_level != m_spindle_level) {
        drive(kSpindlePulse, slot_level);
        sample_carriage();
    }
    if (force || index_level != m_index) drive(kIndex, index_level);
    if (!force && m_spindle_level && !slot_level && pid_running() && !passes.empty()) {
        passes.back().thread.x_mm.push_back(m_cut_sign * train.carriage_mm());
        passes.back().motor_pulses.push_back(motor_pulses);
    }
    m_spindle_level = slot_level;
    m_index = index_level;
}

void LatheRig::update_keypad() {
    std::array<bool, 4> columns{};
    for (int col = 0; col < 4; ++col) columns[static_cast<std::size_t>(col)] = chip.pin_level(Pin{'B', 7 - col});
    const std::array<bool, 4> rows = keypad.rows(columns);
    for (std::size_t row = 0; row < 4; ++row) {
        auto& level = m_row_level[row];
        if (level != static_cast<int>(rows[row])) drive(Pin{'B', 3 - static_cast<int>(row)}, rows[row]);
        level = rows[row];
    }
}

// A pass starts when doCut starts the PID (at the spindle index) and ends when it stops it before the brake.
void LatheRig::record(double dt_s) {
    const bool running = pid_running();
    if (running && !m_was_running) {
        if (passes.empty()) m_cut_sign = chip.pin_level(kDir1) ? 1.0 : -1.0;  // DIR1 high: positive volts
        passes.emplace_back();
        passes.back().start_s = now_s();
        passes.back().thread.x_mm.push_back(m_cut_sign * train.carriage_mm());
        passes.back().motor_pulses.push_back(motor_pulses);
        passes.back().spindle_min_rpm = spindle.rpm();
    }
    if (running) {
        RecordedPass& p = passes.back();
        const std::uint16_t duty = chip.timer(1).ocr(avr::Channel::A);
        p.pid_s += dt_s;
        if (duty >= 1023) p.at_full_s += dt_s;
        if (duty == 0) p.at_zero_s += dt_s;
        p.spindle_min_rpm = std::min(p.spindle_min_rpm, spindle.rpm());
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

// The tool cuts while the PID runs the pass (the machinist set the depth before pressing OK).
void LatheRig::step() {
    const Cycle to = chip.cycle() + kStepCycles;
    const double dt = static_cast<double>(to - m_last) * m_cycle_period_s +
                      ps_to_s(chip.clock().jitter_ps(to) - chip.clock().jitter_ps(m_last));
    m_last = to;
    bridge.en_a = chip.pin_level(kEnA);
    bridge.in1 = chip.pin_level(kDir1);
    bridge.in2 = chip.pin_level(kDir2);
    motor.advance(dt, bridge.mode(), bridge.drive_volts(), 0.0);
    train.follow(motor.state().angle_rad);
    chip.run_until(to);
    spindle.advance_to(now_s(), pid_running() ? m_cut_torque_nm : 0.0);
    const bool level = motor_encoder.y_at(motor.state().angle_rad / (2 * kPi));
    if (level != m_motor_level) {
        drive(kMotorPulse, level);
        sample_carriage();
    }
    if (m_motor_level && !level) ++motor_pulses;
    m_motor_level = level;
    record(dt);
    update_spindle(false);
    update_keypad();
    m_transcript.tick(now_s());
}

void LatheRig::run_for(double s) {
    const Cycle end = chip.cycle() + static_cast<Cycle>(s * static_cast<double>(chip.clock().hz()));
    while (chip.cycle() < end) {
        step();
        if (m_on_slice && chip.cycle() >= m_next_slice) {
            m_next_slice = chip.cycle() + m_slice_cycles;
            m_on_slice(now_s());
        }
    }
}

void LatheRig::on_slice(double every_s, std::function<void(double now_s)> f) {
    m_slice_cycles = std::max<Cycle>(kStepCycles, static_cast<Cycle>(every_s * kFcpuHz));
    m_next_slice = chip.cycle() + m_slice_cycles;
    m_on_slice = std::move(f);
}

void LatheRig::press(char key) {
    hold(key, kKeyHeldS);
    run_for(kKeyReleasedS);
}

void LatheRig::type(const std::string& keys) {
    for (const char k : keys) press(k);
}

void LatheRig::hold(char key, double s) {
    keypad.press(key);
    run_for(s);
    keypad.release_all();
}

}  // namespace cnc::lathe
