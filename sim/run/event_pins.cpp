#include "run/event_pins.hpp"

#include <limits>

#include "common/sc_time.hpp"
#include "common/units.hpp"

namespace cnc::sim {

EventPins::EventPins(const sc_core::sc_module_name& name, const std::vector<ScenarioEvent>& events,
                     sc_core::sc_signal<bool>& estop, sc_core::sc_signal<bool>& lid_open)
    : sc_module(name), m_events(events), m_estop(estop), m_lid_open(lid_open) {
    SC_HAS_PROCESS(EventPins);
    SC_THREAD(run);
}

TimePs EventPins::quiet_until_ps() const {
    return m_next < m_events.size() ? s_to_ps(m_events[m_next].at_s) : std::numeric_limits<TimePs>::max();
}

void EventPins::run() {
    for (; m_next < m_events.size(); ++m_next) {
        const ScenarioEvent& e = m_events[m_next];
        const TimePs at = s_to_ps(e.at_s);
        if (at > now_ps()) wait_ps(at - now_ps());
        (e.input == SafetyInput::Estop ? m_estop : m_lid_open).write(e.active);
    }
}

}  // namespace cnc::sim
