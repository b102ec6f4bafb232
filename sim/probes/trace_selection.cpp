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

bool names_signal(const std::string& requested, const std::string& block, const std::string& name) {
    return requested == name || (!block.empty() && requested == block + "." + name);
}

std::vector<std::size_t> select_traced(const Scenario& s, const std::vector<TraceCandidate>& all) {
    const std::string key = s.file + ": trace.signals";
    std::vector<std::size_t> out;
    for (const std::string& requested : s.trace_signals) {
        const auto named = [&](const TraceCandidate& c) { return names_signal(requested, c.block, c.name); };
        const auto it = std::find_if(all.begin(), all.end(), named);
        if (it == all.end()) {
            throw BadInput(key, "'" + requested + "' is not a signal of " + s.architecture +
                                    " (allowed: " + allowed_names(all) + ", or each as BLOCK.NAME)");
        }
        const auto k = static_cast<std::size_t>(it - all.begin());
        if (std::find(out.begin(), out.end(), k) != out.end()) {
            throw BadInput(key, "'" + requested + "' names " + it->name + " a second time");
        }
        out.push_back(k);
    }
    if (s.trace_signals.empty()) {
        for (std::size_t i = 0; i < all.size(); ++i) {
            if (!all[i].on_request) out.push_back(i);
        }
    }
    std::sort(out.begin(), out.end());  // the architecture's order
    return out;
}

}  // namespace cnc::sim
