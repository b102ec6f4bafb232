#include "common/warning.hpp"

namespace cnc {

std::string to_string(const Warning& w) {
    return w.where.empty() ? w.text : w.where + ": " + w.text;
}

std::vector<WarningGroup> group_warnings(const std::vector<Warning>& warnings) {
    std::vector<WarningGroup> groups;
    for (std::size_t i = 0; i < warnings.size(); ++i) {
        const Warning& w = warnings[i];
        std::size_t g = 0;
        while (g < groups.size() && groups[g].kind != w.kind) ++g;
        if (g == groups.size()) groups.push_back({w.kind, 0, {}, w.text, {}});
        WarningGroup& group = groups[g];
        ++group.count;
        group.members.push_back(i);
        if (!w.where.empty() && group.first.size() < kWarningPlacesShown) group.first.push_back(w.where);
    }
    return groups;
}

std::string summary_line(const WarningGroup& g) {
    if (g.count == 1) return g.first.empty() ? g.message : g.first.front() + ": " + g.message;
    std::string line = std::to_string(g.count) + " x " + g.kind;
    for (std::size_t i = 0; i < g.first.size(); ++i) line += (i > 0 ? ", " : " at ") + g.first[i];
    if (!g.first.empty() && g.count > g.first.size()) line += ", ...";
    return line + "; first: " + g.message;
}

}  // namespace cnc
