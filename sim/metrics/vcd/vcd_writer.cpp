// VCD writer: the header and $dumpvars at construction, then one "#tick" line per instant with changes.
#include "metrics/vcd/vcd_writer.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <ostream>
#include <set>
#include <stdexcept>

#include "common/bad_input.hpp"
#include "metrics/vcd/vcd_timescale.hpp"

namespace cnc::metrics {

namespace {

// Short identifiers from the printable ASCII range '!'..'~', as VCD writers use, without '$': sigrok-cli 0.7.2
// (libsigrok 0.5.2) drops the changes of a variable whose identifier has it.
std::string vcd_id(std::size_t n) {
    constexpr std::size_t kBase = '~' - '!';  // the range less '$'
    std::string id;
    do {
        const char c = static_cast<char>('!' + n % kBase);
        id += c >= '$' ? static_cast<char>(c + 1) : c;
        n /= kBase;
    } while (n > 0);
    return id;
}

// The $timescale text, or BadInput(where, ...) when the standard does not allow the value.
std::string timescale_text(std::int64_t timescale_fs, const std::string& where) {
    const std::optional<std::string> text = format_vcd_timescale(timescale_fs);
    if (!text) {
        throw BadInput(where, "timescale " + std::to_string(timescale_fs) + " fs is not 1, 10 or 100 of fs .. s");
    }
    return *text;
}

std::string real_text(double value) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "r%.16g", value);
    return buf;
}

std::optional<TimePs> exact_period_ps(const VcdSignal& s) {
    return s.clock_hz ? whole_period_ps(*s.clock_hz) : std::nullopt;
}

// The coarsest timescale that keeps every clocked edge exact (1 fs always does).
std::string coarsest_exact_timescale(const std::vector<VcdSignal>& signals) {
    for (const std::string& name : vcd_timescale_names()) {
        const std::int64_t ts = *parse_vcd_timescale_fs(name);
        const bool exact = std::all_of(signals.begin(), signals.end(), [ts](const VcdSignal& s) {
            const std::optional<TimePs> period = exact_period_ps(s);
            return !period || on_vcd_tick(*period, ts);
        });
        if (exact) return name;
    }
    return "1 fs";
}

bool has_space(const std::string& text) {
    return std::any_of(text.begin(), text.end(), [](unsigned char c) { return std::isspace(c) != 0; });
}

// The scopes in the order their first signal comes; "" (the top scope's own signals) among them.
std::vector<std::string> scopes_in_order(const std::vector<VcdSignal>& signals) {
    std::vector<std::string> scopes;
    for (const VcdSignal& s : signals) {
        if (std::find(scopes.begin(), scopes.end(), s.scope) == scopes.end()) scopes.push_back(s.scope);
    }
    return scopes;
}

}  // namespace

std::int64_t auto_timescale_fs(const std::vector<VcdSignal>& signals) {
    constexpr std::int64_t kDefaultFs = 100'000;  // 100 ps: every 50 MHz FPGA and 16 or 8 MHz AVR edge
    for (const std::string& name : vcd_timescale_names()) {
        const std::int64_t ts = *parse_vcd_timescale_fs(name);
        if (ts > kDefaultFs) continue;
        const bool exact = std::all_of(signals.begin(), signals.end(), [ts](const VcdSignal& s) {
            const std::optional<TimePs> period = exact_period_ps(s);
            return !period || on_vcd_tick(*period, ts);
        });
        if (exact) return ts;
    }
    return 1;
}

std::int64_t chosen_timescale_fs(std::optional<std::int64_t> asked_fs, const std::vector<VcdSignal>& signals) {
    return asked_fs ? *asked_fs : auto_timescale_fs(signals);
}

void check_vcd_signals(std::int64_t timescale_fs, const std::vector<VcdSignal>& signals, const std::string& where) {
    (void)timescale_text(timescale_fs, where);
    std::set<std::string> names;
    for (const VcdSignal& s : signals) {
        if (s.name.empty() || has_space(s.name)) {
            throw BadInput(where, "signal name '" + s.name + "' is empty or contains white space");
        }
        if (has_space(s.scope)) throw BadInput(where, "scope name '" + s.scope + "' contains white space");
        if (!names.insert(s.name).second) throw BadInput(where, "signal '" + s.name + "' given twice");
        const std::optional<TimePs> period = exact_period_ps(s);
        if (period && !on_vcd_tick(*period, timescale_fs)) {
            throw BadInput(where, *format_vcd_timescale(timescale_fs) + " would round the edges of " + s.name +
                                      " (its clock, " + std::to_string(*s.clock_hz) + " Hz, has a period of " +
                                      std::to_string(*period) + " ps); the coarsest timescale that keeps every " +
                                      "clocked edge exact is " + coarsest_exact_timescale(signals));
        }
    }
}

std::optional<TimePs> whole_period_ps(std::int64_t clock_hz) {
    if (clock_hz <= 0 || kPsPerSec % clock_hz != 0) return std::nullopt;
    return kPsPerSec / clock_hz;
}

VcdWriter::VcdWriter(std::ostream& out, std::int64_t timescale_fs, std::vector<VcdSignal> signals,
                     const std::string& where, TimePs start_ps)
    : m_out(out),
      m_timescale_fs(timescale_fs),
      m_signals(std::move(signals)),
      m_last_ps(start_ps),
      m_written_tick(ps_to_vcd_ticks(start_ps, timescale_fs)) {
    check_vcd_signals(timescale_fs, m_signals, where);
    m_out << "$version cncsim $end\n$timescale " << timescale_text(timescale_fs, where) << " $end\n$scope module "
          << kVcdTopScope << " $end\n";
    for (std::size_t i = 0; i < m_signals.size(); ++i) m_ids.push_back(vcd_id(i));
    for (const std::string& scope : scopes_in_order(m_signals)) {
        if (!scope.empty()) m_out << "$scope module " << scope << " $end\n";
        for (std::size_t i = 0; i < m_signals.size(); ++i) {
            if (m_signals[i].scope != scope) continue;
            const bool real = m_signals[i].kind == VcdVarKind::Real;
            m_out << (real ? "$var real 64 " : "$var wire 1 ") << m_ids[i] << ' ' << m_signals[i].name << " $end\n";
        }
        if (!scope.empty()) m_out << "$upscope $end\n";
    }
    m_out << "$upscope $end\n$enddefinitions $end\n#" << m_written_tick << "\n$dumpvars\n";
    for (std::size_t i = 0; i < m_signals.size(); ++i) {
        const VcdSignal& s = m_signals[i];
        if (s.kind == VcdVarKind::Real)
            m_out << real_text(s.initial_value) << ' ' << m_ids[i] << '\n';
        else
            m_out << (s.initial ? '1' : '0') << m_ids[i] << '\n';
    }
    m_out << "$end\n";
}

void VcdWriter::write_time(TimePs t_ps) {
    if (t_ps < m_last_ps) {
        throw std::logic_error("VCD writer: time goes back from " + std::to_string(m_last_ps) + " ps to " +
                               std::to_string(t_ps) + " ps");
    }
    m_last_ps = t_ps;
    const std::int64_t tick = ps_to_vcd_ticks(t_ps, m_timescale_fs);
    if (tick != m_written_tick) {
        m_out << '#' << tick << '\n';
        m_written_tick = tick;
    }
}

void VcdWriter::change(TimePs t_ps, std::size_t index, bool level) {
    const VcdSignal& s = m_signals.at(index);
    if (s.kind != VcdVarKind::Wire) throw std::logic_error("VCD writer: " + s.name + " is a real variable, not a wire");
    const std::optional<TimePs> period = exact_period_ps(s);
    if (period && t_ps % *period != 0) {
        throw std::logic_error("VCD writer: edge of " + s.name + " at " + std::to_string(t_ps) +
                               " ps is not on its clock (period " + std::to_string(*period) + " ps)");
    }
    write_time(t_ps);
    m_out << (level ? '1' : '0') << m_ids[index] << '\n';
}

void VcdWriter::change_real(TimePs t_ps, std::size_t index, double value) {
    if (m_signals.at(index).kind != VcdVarKind::Real) {
        throw std::logic_error("VCD writer: " + m_signals[index].name + " is a wire, not a real variable");
    }
    write_time(t_ps);
    m_out << real_text(value) << ' ' << m_ids[index] << '\n';
}

void VcdWriter::finish(TimePs t_ps) {
    write_time(t_ps);
    m_out.flush();
}

namespace {

struct Change {
    TimePs t_ps;
    std::size_t log;
    bool level;
};

const char* const kWhere = "write_vcd";

void check_edges(const EdgeLog& log, std::int64_t timescale_fs) {
    TimePs previous = 0;
    for (const Edge& e : log.edges) {
        if (e.t_ps < previous) {
            throw BadInput(kWhere, "signal '" + log.name + "': edge at " + std::to_string(e.t_ps) +
                                       " ps is negative or out of time order");
        }
        if (!on_vcd_tick(e.t_ps, timescale_fs)) {
            throw BadInput(kWhere, "signal '" + log.name + "': edge at " + std::to_string(e.t_ps) +
                                       " ps is not a multiple of the timescale (" +
                                       timescale_text(timescale_fs, kWhere) + ")");
        }
        previous = e.t_ps;
    }
}

}  // namespace

void write_vcd(std::ostream& out, const std::vector<EdgeLog>& logs, std::int64_t timescale_fs) {
    (void)timescale_text(timescale_fs, kWhere);  // before the edges are checked against it
    std::vector<VcdSignal> signals;
    std::vector<Change> changes;
    for (std::size_t i = 0; i < logs.size(); ++i) {
        check_edges(logs[i], timescale_fs);
        signals.push_back({logs[i].name, logs[i].initial, std::nullopt});
        for (const Edge& e : logs[i].edges) changes.push_back({e.t_ps, i, e.level});
    }
    VcdWriter writer(out, timescale_fs, std::move(signals), kWhere);
    // Stable: changes at one instant keep their order within a log (a zero-width glitch stays a glitch).
    std::stable_sort(changes.begin(), changes.end(), [](const Change& a, const Change& b) { return a.t_ps < b.t_ps; });
    for (const Change& c : changes) writer.change(c.t_ps, c.log, c.level);
    if (!changes.empty()) writer.finish(changes.back().t_ps);
}

}  // namespace cnc::metrics
