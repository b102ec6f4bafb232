#include "probes/trace_selection.hpp"

#include <algorithm>

#include "common/bad_input.hpp"

namespace cnc::sim {

namespace {

std::string allowed_names(const std::vector<TraceCandidate>& all) {
    std::string names;
    for (const TraceCandidate& c : all) names += (names.empty() ? "" : ", ") + c.name;
    return names;
}

}  // namespace

std::vector<std::size_t> select_traced(const Scenario& s, const std::vector<TraceCandidate>& all) {
    const std::string key = s.file + ": trace.signals";
    for (const std::string& name : s.trace_signals) {
        const auto named = [&](const TraceCandidate& c) { return name == c.name; };
        if (std::none_of(all.begin(), all.end(), named)) {
            throw BadInput(
                key, "'" + name + "' is not a signal of " + s.architecture + " (allowed: " + allowed_names(all) + ")");
        }
        if (std::count(s.trace_signals.begin(), s.trace_signals.end(), name) > 1) {
            throw BadInput(key, "'" + name + "' is named twice");
        }
    }
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const bool named =
            std::find(s.trace_signals.begin(), s.trace_signals.end(), all[i].name) != s.trace_signals.end();
        if (s.trace_signals.empty() ? !all[i].on_request : named) out.push_back(i);
    }
    return out;
}

}  // namespace cnc::sim
