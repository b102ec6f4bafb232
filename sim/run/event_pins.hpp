// The scenario's [[events]] on the inputs they name: each input's signal set at its events' times, as an operator or
// the machine would set it (the e-stop pressed, the lid opened).
#pragma once
#include <cstddef>
#include <systemc>
#include <vector>

#include "common/units.hpp"
#include "scenario/event_settings.hpp"

namespace cnc::sim {

class EventPins : public sc_core::sc_module {
public:
    // `events` (in time order) must outlive the module.
    EventPins(const sc_core::sc_module_name& name, const std::vector<ScenarioEvent>& events,
              sc_core::sc_signal<bool>& estop, sc_core::sc_signal<bool>& lid_open);

    // The time of the next event not yet applied (none left: the largest time): no input changes before it.
    [[nodiscard]] TimePs quiet_until_ps() const;

private:
    void run();

    const std::vector<ScenarioEvent>& m_events;
    sc_core::sc_signal<bool>& m_estop;
    sc_core::sc_signal<bool>& m_lid_open;
    std::size_t m_next = 0;  // the first event not yet applied
};

}  // namespace cnc::sim
