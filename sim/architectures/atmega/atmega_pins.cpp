#include "architectures/atmega/atmega_pins.hpp"

namespace cnc::sim {

AtmegaPins::AtmegaPins(EdgeRecorder& rec, const host::cad2g::Plan& plan, bool keep_raw)
    : m_pins(rec, keep_raw), m_windows(plan) {}

void AtmegaPins::read_before(TimePs t_ps) {
    const PinSlice s = m_pins.read_before(t_ps);
    m_windows.add({s.n_enbl_x, s.n_enbl_y, s.dir_x, s.dir_y, s.laser}, s.step_y);
}

}  // namespace cnc::sim
