#include "fpga/laser_ctrl.hpp"

namespace cnc::fpga {

LaserCtrl::LaserCtrl(const sc_core::sc_module_name& name, const FpgaConfig& cfg)
    : sc_module(name),
      motion("motion"),
      pkt_valid("pkt_valid"),
      busy("busy"),
      inhibit("inhibit"),
      laser("laser"),
      m_clock(clock_grid(cfg)),
      m_writer("writer") {
    SC_HAS_PROCESS(LaserCtrl);
    SC_METHOD(on_inputs);
    sensitive << pkt_valid << busy << inhibit << m_engrave;
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
        m_writer.at(next_edge_ps, [this, engrave] { m_engrave.write(engrave); });
    }
    if (busy.event() || inhibit.event() || m_engrave.event()) {
        const bool on = m_engrave.read() && busy.read() && !inhibit.read();
        m_writer.at(next_edge_ps, [this, on] { laser.write(on); });
    }
}

}  // namespace cnc::fpga
