#include "probes/vcd_trace.hpp"

#include <algorithm>

#include <sysc/kernel/sc_dynamic_processes.h>

#include "probes/trace_selection.hpp"

namespace cnc::sim {

namespace {

TimePs now_ps() {
    return static_cast<TimePs>(sc_core::sc_time_stamp().value());
}

std::vector<TraceCandidate> candidates(const std::vector<TracedPin>& pins, const std::vector<TracedReal>& reals) {
    std::vector<TraceCandidate> all;
    for (const TracedPin& p : pins) all.push_back({p.signal->basename(), p.on_request, p.block});
    for (const TracedReal& r : reals) all.push_back({r.signal->basename(), false, r.block});
    return all;
}

template <typename F>
void spawn_on(const sc_core::sc_event& event, const std::string& name, F f) {
    sc_core::sc_spawn_options opts;
    opts.spawn_method();
    opts.dont_initialize();
    opts.set_sensitivity(&event);
    sc_core::sc_spawn(std::move(f), ("vcd_" + name).c_str(), &opts);
}

}  // namespace

bool trace_names_any(const Scenario& s, const char* block, std::initializer_list<const char*> names) {
    if (s.vcd_path.empty()) return false;
    return std::any_of(names.begin(), names.end(), [&](const char* n) {
        return std::any_of(s.trace_signals.begin(), s.trace_signals.end(),
                           [&](const std::string& requested) { return names_signal(requested, block, n); });
    });
}

template <typename Write, typename Keep>
void VcdTrace::change(Write write, Keep keep) {
    const TimePs t_ps = now_ps();
    if (m_ended) return;
    if (m_to_ps && t_ps > *m_to_ps) {
        if (!m_writer) open_at(m_from_ps);
        m_writer->finish(*m_to_ps);
        m_layout.to_ps = *m_to_ps;
        m_ended = true;
        return;
    }
    if (!m_writer) {
        if (t_ps < m_from_ps) {
            keep();  // the values at the window's start are the last before it
            return;
        }
        open_at(m_from_ps);
    }
    write(*m_writer, t_ps);
    if (m_file->failed()) m_ended = true;  // nothing more to write; close() reports it
}

VcdTrace::VcdTrace(const Scenario& s, const std::vector<TracedPin>& pins, const std::vector<TracedReal>& reals)
    : m_timescale_fs(0),
      m_timescale_key(s.file + ": trace.timescale"),
      m_from_ps(s.trace_from_ps),
      m_to_ps(s.trace_to_ps) {
    const std::vector<TraceCandidate> all = candidates(pins, reals);
    const std::vector<std::size_t> chosen = select_traced(s, all);
    m_layout.top_scope = metrics::kVcdTopScope;
    m_layout.from_ps = m_from_ps;
    for (const std::size_t k : chosen) {
        if (k < pins.size()) {
            m_signals.push_back({all[k].name, pins[k].signal->read(), pins[k].clock_hz});
            m_layout.signals.push_back({all[k].block, all[k].name});
        } else {
            const TracedReal& r = reals[k - pins.size()];
            m_signals.push_back({all[k].name, false, std::nullopt, metrics::VcdVarKind::Real, r.signal->read()});
            m_layout.signals.push_back({all[k].block, all[k].name, true, r.sampled});
        }
        m_signals.back().scope = all[k].block;
    }
    m_timescale_fs = metrics::chosen_timescale_fs(s.vcd_timescale_fs, m_signals);
    m_layout.timescale_fs = m_timescale_fs;
    metrics::check_vcd_signals(m_timescale_fs, m_signals, m_timescale_key);  // before the file: a refusal leaves none
    m_file.emplace(s.vcd_path, "the VCD");
    if (m_from_ps == 0) open_at(0);

    for (std::size_t i = 0; i < chosen.size(); ++i) {
        if (chosen[i] < pins.size()) {
            const auto* signal = pins[chosen[i]].signal;
            spawn_on(signal->value_changed_event(), all[chosen[i]].name, [this, signal, i] {
                change([&](metrics::VcdWriter& w, TimePs t) { w.change(t, i, signal->read()); },
                       [&] { m_signals[i].initial = signal->read(); });
            });
        } else {
            const auto* signal = reals[chosen[i] - pins.size()].signal;
            spawn_on(signal->value_changed_event(), all[chosen[i]].name, [this, signal, i] {
                change([&](metrics::VcdWriter& w, TimePs t) { w.change_real(t, i, signal->read()); },
                       [&] { m_signals[i].initial_value = signal->read(); });
            });
        }
    }
}

void VcdTrace::open_at(TimePs t_ps) {
    m_writer.emplace(m_file->stream(), m_timescale_fs, m_signals, m_timescale_key, t_ps);
}

void VcdTrace::close() {
    if (!m_ended) {
        const TimePs end_ps = m_to_ps ? std::min(*m_to_ps, now_ps()) : now_ps();
        if (!m_writer) open_at(m_from_ps);  // nothing changed in the window: the last levels hold through it
        m_layout.to_ps = std::max(end_ps, m_from_ps);
        m_writer->finish(m_layout.to_ps);
    }
    m_ended = true;
    m_file->close();
}

}  // namespace cnc::sim
