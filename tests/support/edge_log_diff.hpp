// Where two edge logs of one pin part: for the tests that require two implementations to drive a pin alike.
#pragma once
#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string>

#include "common/edge_log.hpp"

namespace cnc::test {

// "" when the two logs are the same, else their first difference (time in ps, levels; "-" past a log's end).
inline std::string first_difference(const EdgeLog& a, const EdgeLog& b) {
    std::ostringstream s;
    if (a.initial != b.initial) {
        s << "initial level " << a.initial << " vs " << b.initial;
        return s.str();
    }
    const std::size_t n = std::max(a.edges.size(), b.edges.size());
    for (std::size_t i = 0; i < n; ++i) {
        const bool in_a = i < a.edges.size();
        const bool in_b = i < b.edges.size();
        if (in_a && in_b && a.edges[i].t_ps == b.edges[i].t_ps && a.edges[i].level == b.edges[i].level) continue;
        s << "edge #" << i << ": ";
        if (in_a) {
            s << a.edges[i].level << " at " << a.edges[i].t_ps << " ps";
        } else {
            s << "-";
        }
        s << " vs ";
        if (in_b) {
            s << b.edges[i].level << " at " << b.edges[i].t_ps << " ps";
        } else {
            s << "-";
        }
        return s.str();
    }
    return "";
}

}  // namespace cnc::test
