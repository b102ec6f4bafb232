#include "systems/atmega/enabled_steps.hpp"

#include <cstddef>

namespace cnc::sim {

EdgeLog enabled_steps(const EdgeLog& step, const EdgeLog& n_enbl) {
    EdgeLog out;
    out.name = step.name;
    out.initial = false;
    std::size_t e = 0;
    bool disabled = n_enbl.initial;
    bool in_pulse = false;
    for (const Edge& s : step.edges) {
        while (e < n_enbl.edges.size() && n_enbl.edges[e].t_ps < s.t_ps) disabled = n_enbl.edges[e++].level;
        if (s.level && !disabled) {
            out.add(s.t_ps, true);
            in_pulse = true;
        } else if (!s.level && in_pulse) {
            out.add(s.t_ps, false);
            in_pulse = false;
        }
    }
    return out;
}

}  // namespace cnc::sim
