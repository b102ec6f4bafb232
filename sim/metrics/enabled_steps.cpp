#include "metrics/enabled_steps.hpp"

#include <cstddef>

namespace cnc::metrics {

EdgeLog enabled_steps(const EdgeLog& step, const EdgeLog& enable, EnableLevel active) {
    const bool enabled_level = active == EnableLevel::ActiveHigh;
    EdgeLog out;
    out.name = step.name;
    out.initial = false;
    std::size_t e = 0;
    bool enabled = enable.initial == enabled_level;
    bool in_pulse = false;
    for (const Edge& s : step.edges) {
        while (e < enable.edges.size() && enable.edges[e].t_ps < s.t_ps) {
            enabled = enable.edges[e++].level == enabled_level;
        }
        if (s.level && enabled) {
            out.add(s.t_ps, true);
            in_pulse = true;
        } else if (!s.level && in_pulse) {
            out.add(s.t_ps, false);
            in_pulse = false;
        }
    }
    return out;
}

}  // namespace cnc::metrics
