#include "architectures/avr_board/driven_pins.hpp"

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

DrivenPins::DrivenPins(EdgeRecorder& rec, bool keep_raw)
    : m_rec(rec),
      m_keep_raw(keep_raw),
      // The DRV8825's nENBL is active low.
      m_driven_x(rec.log("n_enbl_x").initial, metrics::EnableLevel::ActiveLow),
      m_driven_y(rec.log("n_enbl_y").initial, metrics::EnableLevel::ActiveLow) {
    for (const char* pin : {"dir_x", "dir_y", "laser"}) m_unread[pin] = empty_like(rec.log(pin));
    for (const char* pin : {"step_x", "step_y"}) m_unread[pin] = EdgeLog{pin, false, {}};  // enabled_steps' initial
    if (!keep_raw) return;
    for (const char* pin : {"n_enbl_x", "n_enbl_y", "step_x", "step_y"}) m_raw[pin] = empty_like(rec.log(pin));
}

PinSlice DrivenPins::read_before(TimePs t_ps) {
    PinSlice s;
    s.dir_x = m_rec.take_before("dir_x", t_ps);
    s.dir_y = m_rec.take_before("dir_y", t_ps);
    s.n_enbl_x = m_rec.take_before("n_enbl_x", t_ps);
    s.n_enbl_y = m_rec.take_before("n_enbl_y", t_ps);
    s.laser = m_rec.take_before("laser", t_ps);
    const EdgeLog raw_x = m_rec.take_before("step_x", t_ps);
    const EdgeLog raw_y = m_rec.take_before("step_y", t_ps);
    s.step_x = m_driven_x.add(raw_x, s.n_enbl_x);
    s.step_y = m_driven_y.add(raw_y, s.n_enbl_y);
    append(m_unread["step_x"], s.step_x);
    append(m_unread["step_y"], s.step_y);
    append(m_unread["dir_x"], s.dir_x);
    append(m_unread["dir_y"], s.dir_y);
    append(m_unread["laser"], s.laser);
    if (m_keep_raw) {
        append(m_raw["n_enbl_x"], s.n_enbl_x);
        append(m_raw["n_enbl_y"], s.n_enbl_y);
        append(m_raw["step_x"], raw_x);
        append(m_raw["step_y"], raw_y);
    }
    return s;
}

EdgeLog DrivenPins::hand_over(const std::string& pin, TimePs before_ps) {
    return m_unread.at(pin).take_before(before_ps);
}

EdgeLog DrivenPins::take_raw(const std::string& pin) {
    return std::move(m_raw.at(pin));
}

}  // namespace cnc::sim
