#include "metrics/pulse/enabled_steps.hpp"

#include <cstddef>

namespace cnc::metrics {

EnabledStepsFold::EnabledStepsFold(bool enable_initial, EnableLevel active)
    : m_enabled_level(active == EnableLevel::ActiveHigh), m_enabled(enable_initial == m_enabled_level) {}

EdgeLog EnabledStepsFold::add(const EdgeLog& step, const EdgeLog& enable) {
    EdgeLog out;
    out.name = step.name;
    out.initial = false;
    std::size_t e = 0;
    for (const Edge& s : step.edges) {
        while (e < enable.edges.size() && enable.edges[e].t_ps < s.t_ps) {
            m_enabled = enable.edges[e++].level == m_enabled_level;
        }
        if (s.level && m_enabled) {
            out.add(s.t_ps, true);
            m_in_pulse = true;
        } else if (!s.level && m_in_pulse) {
            out.add(s.t_ps, false);
            m_in_pulse = false;
        }
    }
    // The next piece's STEP edges come after every enable edge of this one.
    if (!enable.edges.empty()) m_enabled = enable.edges.back().level == m_enabled_level;
    return out;
}

EdgeLog enabled_steps(const EdgeLog& step, const EdgeLog& enable, EnableLevel active) {
    return EnabledStepsFold(enable.initial, active).add(step, enable);
}

}  // namespace cnc::metrics
