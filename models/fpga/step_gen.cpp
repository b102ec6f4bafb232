#include "fpga/step_gen.hpp"

#include <algorithm>

namespace cnc::fpga {

StepGen::StepGen(const sc_core::sc_module_name& name, const FpgaConfig& cfg)
    : sc_module(name),
      steps_x("steps_x"),
      steps_y("steps_y"),
      feed_rate("feed_rate"),
      pkt_valid("pkt_valid"),
      numerator_x("numerator_x"),
      numerator_y("numerator_y"),
      ramp_accel("ramp_accel"),
      ramp_start("ramp_start"),
      ramp_jerk("ramp_jerk"),
      cfg_valid("cfg_valid"),
      dir_x("dir_x"),
      step_x("step_x"),
      dir_y("dir_y"),
      step_y("step_y"),
      busy("busy"),
      m_cfg(cfg),
      m_clock(clock_grid(cfg)),
      m_num_x(cfg.numerator_default),  // seed 000 §5.2.4 NUMERATOR_DEFAULT
      m_num_y(cfg.numerator_default),
      m_ramp_accel(cfg.ramp_accel_default),
      m_ramp_start(cfg.ramp_start_default),
      m_ramp_jerk(cfg.ramp_jerk_default) {
    SC_HAS_PROCESS(StepGen);
    SC_METHOD(on_pkt_valid);
    sensitive << pkt_valid;
    dont_initialize();
    SC_METHOD(on_cfg_valid);
    sensitive << cfg_valid;
    dont_initialize();
    SC_METHOD(emit_edges);
    sensitive << m_edge_due;
    dont_initialize();
}

void StepGen::on_cfg_valid() {
    ++m_activations;
    if (!cfg_valid.read()) return;
    // cfg_valid high at edge k is seen at k+1; latched only if the FSM is IDLE there (an init mid-move is lost).
    if (idle_at_edge(m_clock.first_after(now_ps()))) {
        m_num_x = numerator_x.read();
        m_num_y = numerator_y.read();
        m_ramp_accel = ramp_accel.read();
        m_ramp_start = ramp_start.read();
        m_ramp_jerk = ramp_jerk.read();
    }
}

void StepGen::on_pkt_valid() {
    ++m_activations;
    if (!pkt_valid.read()) return;
    const std::int64_t k = m_clock.last_at_or_before(now_ps());
    Move move;
    move.t_pkt_valid_ps = m_clock.at(k);
    if (!idle_at_edge(k + 1)) {  // SETUP/DIR_WAIT/RUN/DONE ignore pkt_valid: the packet is lost
        m_moves.push_back(move);
        return;
    }
    // The decoder's fields only change with pkt_valid, so the values SETUP (k+2) and DIR_WAIT (k+3) read are
    // the ones present now; num_x/num_y cannot change outside IDLE.
    const MoveInputs in{steps_x.read(), steps_y.read(), feed_rate.read(), m_num_x,
                        m_num_y,        m_ramp_accel,   m_ramp_start,     m_ramp_jerk};
    m_schedule.emplace(in, m_dir_x, m_dir_y, m_cfg);
    m_move_edge = k;
    m_dir_x = m_schedule->dir_x();
    m_dir_y = m_schedule->dir_y();
    m_idle_from = k + m_schedule->idle_from();
    move.accepted = true;
    move.periods = m_schedule->periods();
    if (m_schedule->has_run()) move.t_run_start_ps = m_clock.at(k + m_schedule->run_start());
    move.t_busy_fall_ps = m_clock.at(k + m_schedule->busy_fall());
    m_moves.push_back(move);
    fetch_next_edge();
    notify_next_edge();
}

void StepGen::fetch_next_edge() {
    PinEdge e;
    if (m_schedule->next(e)) {
        m_next = e;
    } else {
        m_next.reset();
    }
}

void StepGen::notify_next_edge() {
    std::optional<std::int64_t> due;
    if (m_next) due = m_move_edge + m_next->cycle;
    if (m_halt_edge && !m_halted) due = due ? std::min(*due, *m_halt_edge) : *m_halt_edge;
    if (due) m_edge_due.notify(ps(m_clock.at(*due) - now_ps()));
}

void StepGen::halt_at(std::int64_t edge) {
    m_halt_edge = edge;
    m_idle_from = std::numeric_limits<std::int64_t>::max();
    m_edge_due.cancel();
    notify_next_edge();
}

void StepGen::halt(std::int64_t edge) {
    m_halted = true;
    m_next.reset();
    m_schedule.reset();
    if (step_x.read()) step_x.write(false);
    if (step_y.read()) step_y.write(false);
    if (busy.read()) busy.write(false);
    // The last move taken (packets ignored while it ran may follow it in the log).
    std::size_t i = m_moves.size();
    while (i > m_moves.first() && !m_moves[i - 1].accepted) --i;
    if (i == m_moves.first()) return;  // no move kept
    Move& last = m_moves[i - 1];
    const TimePs t = m_clock.at(edge);
    if (last.t_busy_fall_ps <= t) return;
    last.t_busy_fall_ps = t;
    if (last.t_run_start_ps > t) last.t_run_start_ps = -1;
}

void StepGen::emit_edges() {
    ++m_activations;
    const std::int64_t edge = m_clock.last_at_or_before(now_ps());
    if (m_halted) return;
    if (m_halt_edge && edge >= *m_halt_edge) {
        halt(edge);
        return;
    }
    while (m_next && m_move_edge + m_next->cycle == edge) {
        const bool level = m_next->level;
        switch (m_next->pin) {
            case StepPin::Busy:
                busy.write(level);
                break;
            case StepPin::DirX:
                dir_x.write(level);
                break;
            case StepPin::DirY:
                dir_y.write(level);
                break;
            case StepPin::StepX:
                step_x.write(level);
                break;
            case StepPin::StepY:
                step_y.write(level);
                break;
        }
        fetch_next_edge();
    }
    notify_next_edge();
}

}  // namespace cnc::fpga
