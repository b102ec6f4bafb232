// Where the tool (carriage) is at a time: what the mechanics record and the path metrics measure.
#pragma once
#include <algorithm>
#include <vector>

#include "common/geometry.hpp"
#include "common/units.hpp"

namespace cnc {

struct ToolSample {
    TimePs t_ps = 0;
    geom::Vec2 pos;
};

// The samples (in time order) before t, taken out of `samples`.
[[nodiscard]] inline std::vector<ToolSample> take_samples_before(std::vector<ToolSample>& samples, TimePs t_ps) {
    const auto end = std::lower_bound(samples.begin(), samples.end(), t_ps,
                                      [](const ToolSample& s, TimePs t) { return s.t_ps < t; });
    std::vector<ToolSample> taken(samples.begin(), end);
    samples.erase(samples.begin(), end);
    return taken;
}

}  // namespace cnc
