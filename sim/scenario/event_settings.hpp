// Scenario events ([[events]]): a machine input changed at a time of the run, as an operator or the machine would
// change it: the e-stop pressed, the laser's lid opened. An architecture that has no such input refuses the event
// (Architecture::check_events), so that a study never reads a run without the event as one with it.
#pragma once
#include <string>
#include <vector>

#include "scenario/key_reader.hpp"

namespace cnc::sim {

enum class SafetyInput { Estop, Lid };

struct ScenarioEvent {
    double at_s = 0.0;
    SafetyInput input = SafetyInput::Estop;
    bool active = true;  // the e-stop pressed, the lid open
    std::string key;     // "events[i].what", for messages
};

// The events in time order (a table out of order is refused, naming it).
void read_events(KeyReader& r, std::vector<ScenarioEvent>& events);

}  // namespace cnc::sim
