#include "fpga/laser_ctrl.hpp"

#include <optional>

#include "fpga/core/laser_pwm.hpp"

namespace cnc::fpga {

LaserCtrl::LaserCtrl(const sc_core::sc_module_name& name, const FpgaConfig& cfg)
    : sc_module(name),
      motion("motion"),
      laser_high("laser_high"),
      pkt_valid("pkt_valid"),
      busy("busy"),
      inhibit("inhibit"),
      laser("laser"),
      m_clock(clock_grid(cfg)),
      m_pwm_period(cfg.laser_pwm_period_cycles),
      m_writer("writer") {
    SC_HAS_PROCESS(LaserCtrl);
    SC_METHOD(on_inputs);
    sensitive << pkt_valid << busy << inhibit << m_engrave;
    dont_initialize();
    SC_METHOD(on_pwm_turn);
    sensitive << m_pwm_turn;
    dont_initialize();
}

void LaserCtrl::add_traces(sc_core::sc_trace_file* tf) const {
    sc_core::sc_trace(tf, m_engrave, m_engrave.name());
}

void LaserCtrl::on_inputs() {
    ++m_activations;
    // Every input is a register of another block (or engrave), so it changed exactly at edge n = now / T and
    // holds until at least edge n+1, whose always block reads it.
    const std::int64_t edge = m_clock.last_at_or_before(now_ps());
    const TimePs next_edge_ps = m_clock.at(edge + 1);
    if (pkt_valid.event() && pkt_valid.read()) {
        const bool engrave = motion.read() != 0;  // G1/G2/G3 engrave, G0 does not
        if (m_pwm_period == 0) {
            m_writer.at(next_edge_ps, [this, engrave] { m_engrave.write(engrave); });
        } else {
            // The high time and the count's restart take effect at edge + 1 even where engrave keeps its value (a
            // packet during a move): the pin is driven again from there.
            const std::uint16_t high = laser_high.read();
            m_writer.at(next_edge_ps, [this, engrave, high, edge] {
                m_engrave.write(engrave);
                m_high = high;
                m_count_zero_edge = edge + 1;
                drive(edge + 1);
            });
        }
    }
    // The count holds while step_gen is idle: a move that starts edges after its packet's restart starts it at 0.
    if (m_pwm_period > 0 && busy.event() && busy.read() && edge > m_count_zero_edge) m_count_zero_edge = edge;
    if (busy.event() || inhibit.event() || m_engrave.event()) drive(edge);
}

void LaserCtrl::on_pwm_turn() {
    ++m_activations;
    drive(m_clock.last_at_or_before(now_ps()));
}

void LaserCtrl::drive(std::int64_t edge) {
    const bool enabled = m_engrave.read() && busy.read() && !inhibit.read();
    const TimePs next_edge_ps = m_clock.at(edge + 1);
    if (m_pwm_period == 0) {
        m_writer.at(next_edge_ps, [this, enabled] { laser.write(enabled); });
        return;
    }
    m_pwm_turn.cancel();
    const std::int64_t count = edge - m_count_zero_edge;
    const bool on = enabled && laser_pwm_high(count, m_high, m_pwm_period);
    m_writer.at(next_edge_ps, [this, on] { laser.write(on); });
    if (!enabled) return;
    if (const std::optional<std::int64_t> turn = laser_pwm_next_change(count, m_high, m_pwm_period)) {
        m_pwm_turn.notify(ps(m_clock.at(edge + *turn) - now_ps()));
    }
}

}  // namespace cnc::fpga
