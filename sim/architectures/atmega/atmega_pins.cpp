#include "architectures/atmega/atmega_pins.hpp"

#include <utility>

namespace cnc::sim {

namespace {

void append(EdgeLog& to, const EdgeLog& from) {
    to.edges.insert(to.edges.end(), from.edges.begin(), from.edges.end());
}

// An empty log of a recorder pin: its name and its level before the run.
EdgeLog empty_like(const EdgeLog& log) {
    return EdgeLog{log.name, log.initial, {}};
}

}  // namespace

AtmegaPins::AtmegaPins(EdgeRecorder& rec, const host::cad2g::Plan& plan, bool keep_raw)
    : m_rec(rec),
      m_keep_raw(keep_raw),
      // The DRV8825's nENBL is active low.
      m_driven_x(rec.log("n_enbl_x").initial, metrics::EnableLevel::ActiveLow),
      m_driven_y(rec.log("n_enbl_y").initial, metrics::EnableLevel::ActiveLow),
      m_windows(plan) {
    for (const char* pin : {"dir_x", "dir_y", "laser"}) m_unread[pin] = empty_like(rec.log(pin));
    for (const char* pin : {"step_x", "step_y"}) m_unread[pin] = EdgeLog{pin, false, {}};  // enabled_steps' initial
    if (!keep_raw) return;
    for (const char* pin : {"n_enbl_x", "n_enbl_y", "step_x", "step_y"}) m_raw[pin] = empty_like(rec.log(pin));
}

void AtmegaPins::read_before(TimePs t_ps) {
    std::map<std::string, EdgeLog> read;
    for (const char* pin : {"step_x", "dir_x", "step_y", "dir_y", "n_enbl_x", "n_enbl_y", "laser"}) {
        read[pin] = m_rec.take_before(pin, t_ps);
    }
    const EdgeLog driven_x = m_driven_x.add(read["step_x"], read["n_enbl_x"]);
    const EdgeLog driven_y = m_driven_y.add(read["step_y"], read["n_enbl_y"]);
    m_windows.add({read["n_enbl_x"], read["n_enbl_y"], read["dir_x"], read["dir_y"], read["laser"]}, driven_y);
    append(m_unread["step_x"], driven_x);
    append(m_unread["step_y"], driven_y);
    for (const char* pin : {"dir_x", "dir_y", "laser"}) append(m_unread[pin], read[pin]);
    if (!m_keep_raw) return;
    for (const char* pin : {"n_enbl_x", "n_enbl_y", "step_x", "step_y"}) append(m_raw[pin], read[pin]);
}

EdgeLog AtmegaPins::hand_over(const std::string& pin, TimePs before_ps) {
    return m_unread.at(pin).take_before(before_ps);
}

EdgeLog AtmegaPins::take_raw(const std::string& pin) {
    return std::move(m_raw.at(pin));
}

}  // namespace cnc::sim
