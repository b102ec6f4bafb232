#include "architectures/lathe_sync/lathe_trace.hpp"

#include <algorithm>

#include "probes/trace_selection.hpp"

namespace cnc::sim {

LatheTrace::LatheTrace(const Scenario& s, std::optional<std::int64_t> clock_hz) : m_s(s) {
    std::vector<TraceCandidate> all;
    for (const lathe::TracedPin& p : lathe::traced_pins()) all.push_back({p.name, false, p.block});
    m_chosen = select_traced(s, all);
    m_layout.top_scope = metrics::kVcdTopScope;
    m_layout.from_ps = s.trace_from_ps;
    for (const std::size_t i : m_chosen) {
        metrics::VcdSignal& signal = m_signals.emplace_back();
        signal.name = all[i].name;
        signal.clock_hz = clock_hz;
        signal.scope = all[i].block;
        m_layout.signals.push_back({all[i].block, all[i].name});
    }
    m_layout.timescale_fs = metrics::chosen_timescale_fs(s.vcd_timescale_fs, m_signals);
    metrics::check_vcd_signals(m_layout.timescale_fs, m_signals, s.file + ": trace.timescale");
    m_file.emplace(s.vcd_path, "the VCD");
}

// The levels at trace.from_s are the rig's initial ones updated by every edge before it.
void LatheTrace::write(const lathe::LatheRig& rig) {
    std::vector<lathe::PinEdge> edges = rig.trace();
    std::stable_sort(edges.begin(), edges.end(),
                     [](const lathe::PinEdge& a, const lathe::PinEdge& b) { return a.cycle < b.cycle; });
    std::vector<int> slot(lathe::traced_pins().size(), -1);  // traced pin -> signal index
    for (std::size_t k = 0; k < m_chosen.size(); ++k) {
        slot[m_chosen[k]] = static_cast<int>(k);
        m_signals[k].initial = rig.trace_initial()[m_chosen[k]];
    }
    const ClockGrid& clock = rig.chip.clock();
    const TimePs end_ps = clock.at(rig.chip.cycle());
    const TimePs to_ps = m_s.trace_to_ps ? std::min(*m_s.trace_to_ps, end_ps) : end_ps;
    std::size_t e = 0;
    for (; e < edges.size() && clock.at(edges[e].cycle) < m_s.trace_from_ps; ++e) {
        if (slot[edges[e].pin] >= 0) m_signals[static_cast<std::size_t>(slot[edges[e].pin])].initial = edges[e].level;
    }
    metrics::VcdWriter vcd(m_file->stream(), m_layout.timescale_fs, m_signals, m_s.file + ": trace.timescale",
                           m_s.trace_from_ps);
    for (; e < edges.size(); ++e) {
        const TimePs t_ps = clock.at(edges[e].cycle);
        if (t_ps > to_ps) break;
        if (slot[edges[e].pin] >= 0) vcd.change(t_ps, static_cast<std::size_t>(slot[edges[e].pin]), edges[e].level);
    }
    m_layout.to_ps = std::max(to_ps, m_s.trace_from_ps);
    vcd.finish(m_layout.to_ps);
    m_file->close();
}

}  // namespace cnc::sim
