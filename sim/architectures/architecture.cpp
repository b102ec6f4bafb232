#include "architectures/architecture.hpp"

#include "scenario/event_settings.hpp"

namespace cnc::sim {

void Architecture::check_events(const KeyReader& r, const std::vector<ScenarioEvent>& events,
                                const ArchSettings& /*settings*/) const {
    if (!events.empty()) r.fail(events.front().key, "the " + name() + " architecture has no e-stop or interlock input");
}

}  // namespace cnc::sim
