#include "probes/vcd_trace.hpp"

#include <algorithm>

#include <sysc/kernel/sc_dynamic_processes.h>

#include "common/bad_input.hpp"

namespace cnc::sim {

namespace {

TimePs now_ps() { return static_cast<TimePs>(sc_core::sc_time_stamp().value()); }

std::string allowed_names(const std::vector<TracedPin>& pins) {
    std::string names;
    for (const TracedPin& p : pins) names += (names.empty() ? "" : ", ") + std::string(p.signal->basename());
    return names;
}

// The pins of the file: those trace.signals names, in the order the architecture lists them, or every pin
// that is not on request.
std::vector<TracedPin> selected_pins(const Scenario& s, const std::vector<TracedPin>& pins) {
    const std::string key = s.file + ": trace.signals";
    std::vector<TracedPin> out;
    for (const std::string& name : s.trace_signals) {
        const auto named = [&](const TracedPin& p) { return name == p.signal->basename(); };
        if (std::none_of(pins.begin(), pins.end(), named)) {
            throw BadInput(key, "'" + name + "' is not a pin of " + s.architecture + " (allowed: " +
                                    allowed_names(pins) + ")");
        }
        if (std::count(s.trace_signals.begin(), s.trace_signals.end(), name) > 1) {
            throw BadInput(key, "'" + name + "' is named twice");
        }
    }
    for (const TracedPin& p : pins) {
        const bool named = std::find(s.trace_signals.begin(), s.trace_signals.end(), p.signal->basename()) !=
                           s.trace_signals.end();
        if (s.trace_signals.empty() ? !p.on_request : named) out.push_back(p);
    }
    return out;
}

}  // namespace

bool trace_names_any(const Scenario& s, std::initializer_list<const char*> names) {
    if (s.vcd_path.empty()) return false;
    return std::any_of(names.begin(), names.end(), [&](const char* n) {
        return std::find(s.trace_signals.begin(), s.trace_signals.end(), n) != s.trace_signals.end();
    });
}

VcdTrace::VcdTrace(const Scenario& s, const std::vector<TracedPin>& pins)
    : m_timescale_fs(s.vcd_timescale_fs),
      m_timescale_key(s.file + ": trace.timescale"),
      m_from_ps(s.trace_from_ps),
      m_to_ps(s.trace_to_ps) {
    const std::vector<TracedPin> traced = selected_pins(s, pins);
    for (const TracedPin& p : traced) m_signals.push_back({p.signal->basename(), p.signal->read(), p.clock_hz});
    metrics::check_vcd_signals(m_timescale_fs, m_signals, m_timescale_key);  // before the file: a refusal leaves none
    m_file.emplace(s.vcd_path, "the VCD");
    if (m_from_ps == 0) open_at(0);

    for (std::size_t i = 0; i < traced.size(); ++i) {
        const sc_core::sc_signal<bool>* signal = traced[i].signal;
        sc_core::sc_spawn_options opts;
        opts.spawn_method();
        opts.dont_initialize();
        opts.set_sensitivity(&signal->value_changed_event());
        sc_core::sc_spawn([this, signal, i] { change(i, signal->read()); },
                          (std::string("vcd_") + signal->basename()).c_str(), &opts);
    }
}

void VcdTrace::open_at(TimePs t_ps) {
    m_writer.emplace(m_file->stream(), m_timescale_fs, m_signals, m_timescale_key, t_ps);
}

void VcdTrace::change(std::size_t index, bool level) {
    const TimePs t_ps = now_ps();
    if (m_ended) return;
    if (m_to_ps && t_ps > *m_to_ps) {
        if (!m_writer) open_at(m_from_ps);
        m_writer->finish(*m_to_ps);
        m_ended = true;
        return;
    }
    if (!m_writer) {
        if (t_ps < m_from_ps) {
            m_signals[index].initial = level;  // the levels at the window's start are the last before it
            return;
        }
        open_at(m_from_ps);
    }
    m_writer->change(t_ps, index, level);
    if (m_file->failed()) m_ended = true;  // nothing more to write; close() reports it
}

void VcdTrace::close() {
    if (!m_ended) {
        const TimePs end_ps = m_to_ps ? std::min(*m_to_ps, now_ps()) : now_ps();
        if (!m_writer) open_at(m_from_ps);  // nothing changed in the window: the last levels hold through it
        m_writer->finish(std::max(end_ps, m_from_ps));
    }
    m_ended = true;
    m_file->close();
}

}  // namespace cnc::sim
