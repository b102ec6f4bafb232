// Logic-level history of one pin: what a logic analyser records, and what every metric is computed from.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "common/units.hpp"

namespace cnc {

struct Edge {
    TimePs t_ps = 0;
    bool level = false;  // level after the edge
};

struct EdgeLog {
    std::string name;      // pin name as in the VCD: step_x, dir_x, laser, ...
    bool initial = false;  // level before the first edge
    std::vector<Edge> edges;

    void add(TimePs t_ps, bool level) { edges.push_back({t_ps, level}); }
    // Level at time t: the level after the last edge at or before t.
    [[nodiscard]] bool level_at(TimePs t_ps) const;
    [[nodiscard]] std::vector<TimePs> rising() const;
    [[nodiscard]] std::vector<TimePs> falling() const;
    [[nodiscard]] std::size_t count_falling() const;
    // Hands over the edges before t_ps and keeps the rest; the level they leave becomes this log's initial one.
    [[nodiscard]] EdgeLog take_before(TimePs t_ps);
};

}  // namespace cnc
