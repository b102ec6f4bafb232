#include "mechanics/drv8825.hpp"
#include "common/sc_time.hpp"
#include "common/splitmix64.hpp"

#include <string>

namespace cnc::mech {

Drv8825::Drv8825(const sc_core::sc_module_name& name, const Drv8825Config& cfg, StepperMotor& motor)
    : sc_core::sc_module(name),
      step("step"),
      dir("dir"),
      n_enbl("n_enbl"),
      m0("m0"),
      m1("m1"),
      m2("m2"),
      m_cfg(cfg),
      m_motor(motor),
      m_checker(cfg.limits),
      m_fault_key(stream_key(cfg.fault_seed, cfg.fault_line)) {
    SC_HAS_PROCESS(Drv8825);
    SC_METHOD(on_step);
    sensitive << step.value_changed();
    dont_initialize();
    SC_METHOD(on_dir);
    sensitive << dir.value_changed();
    dont_initialize();
    SC_METHOD(on_enable);
    sensitive << n_enbl.value_changed();
    dont_initialize();
}

void Drv8825::start_of_simulation() {
    m_dir_level = dir.read();
    m_dir_before = m_dir_level;
    m_checker.set_initial_levels(step.read(), m_dir_level);
    m_motor.on_microstep(0, m_position, kIndexerUnitsPerFullStep);
    m_motor.on_enable(0, !n_enbl.read());
}

void Drv8825::add_traces(sc_core::sc_trace_file* tf) const {
    sc_core::sc_trace(tf, m_position, std::string(name()) + ".position_32nds");
}

void Drv8825::move_to(TimePs t_ps, std::int64_t position) {
    m_position = position;
    m_motor.on_microstep(t_ps, m_position, kIndexerUnitsPerFullStep);
    m_step_ev.notify(sc_core::SC_ZERO_TIME);
}

void Drv8825::on_dir() {
    const TimePs t = now_ps();
    const bool level = dir.read();
    m_checker.on_dir(t, level);
    m_dir_before = m_dir_level;
    m_dir_level = level;
    m_dir_change_ps = t;
}

void Drv8825::on_enable() {
    m_motor.on_enable(now_ps(), !n_enbl.read());
    m_enable_ev.notify(sc_core::SC_ZERO_TIME);
}

void Drv8825::on_step() {
    const TimePs t = now_ps();
    const bool level = step.read();
    m_checker.on_step(t, level);

    if (!level) {
        if (m_cfg.strict && m_pulse_moved && t - m_pulse_rise_ps < m_cfg.limits.step_high_min_ps) {
            --m_stats.steps;
            ++m_stats.ignored_short;
            move_to(t, m_position_before_pulse);
        }
        m_pulse_moved = false;
        m_last_fall_ps = t;
        return;
    }

    // DIR as it was just before this edge, whether on_dir has already run in this time step or not.
    const bool dir_level = m_dir_change_ps == t ? m_dir_before : m_dir_level;
    if (n_enbl.read()) {
        ++m_stats.ignored_disabled;
        return;
    }
    if (m_cfg.strict && m_last_fall_ps >= 0 && t - m_last_fall_ps < m_cfg.limits.step_low_min_ps) {
        ++m_stats.ignored_short;
        return;
    }
    const int microsteps = microsteps_for({m0.read(), m1.read(), m2.read()});
    const int direction = dir_level == m_cfg.dir_high_is_positive ? 1 : -1;
    if (m_cfg.step_loss_rate > 0.0 && unit_draw(m_fault_key, m_rises++) < m_cfg.step_loss_rate) {
        ++m_stats.lost_to_fault;
        m_stats.lost_net_steps += direction;
        return;
    }
    m_pulse_moved = true;
    m_pulse_rise_ps = t;
    m_position_before_pulse = m_position;
    ++m_stats.steps;
    move_to(t, next_indexer_position(m_position, microsteps, direction));
}

}  // namespace cnc::mech
