#include "scenario/event_settings.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace cnc::sim {

void read_events(KeyReader& r, std::vector<ScenarioEvent>& events) {
    const std::size_t n = r.get_table_count(
        "events", "machine inputs changed at a time of the run, one [[events]] table each, in time order (at_s, what)");
    // Table 0 is read even without one, so that the keys are documented.
    for (std::size_t i = 0; i < std::max<std::size_t>(n, 1); ++i) {
        const std::string at_key = "events[" + std::to_string(i) + "].at_s";
        const std::string what_key = "events[" + std::to_string(i) + "].what";
        for (const std::string& key : {at_key, what_key}) {
            if (i < n && !r.has(key)) r.fail(key, "missing: every [[events]] table gives at_s and what");
        }
        ScenarioEvent e;
        e.at_s = r.get_float(at_key, 0.0, 0.0, 1e6, "when the input changes, s of simulated time");
        const std::string what = r.get_choice(
            what_key, "estop-pressed", {"estop-pressed", "estop-released", "lid-opened", "lid-closed"},
            "the change: the e-stop input (fpga.estop) pressed or released, the interlock's lid (fpga.interlock) "
            "opened or closed");
        e.input = what.rfind("estop", 0) == 0 ? SafetyInput::Estop : SafetyInput::Lid;
        e.active = what == "estop-pressed" || what == "lid-opened";
        e.key = what_key;
        if (i >= n) break;
        if (!events.empty() && e.at_s < events.back().at_s) {
            r.fail(at_key, fmt::format(FMT_STRING("{:g} s is before the event above it ({:g} s): list them in time "
                                                  "order"),
                                       e.at_s, events.back().at_s));
        }
        events.push_back(e);
    }
}

}  // namespace cnc::sim
