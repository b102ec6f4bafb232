// VCD writer for edge logs: one scope, 1-bit wires, initial levels in $dumpvars, then the merged edges.
#include <algorithm>
#include <ostream>
#include <set>

#include "common/bad_input.hpp"
#include "metrics/vcd.hpp"
#include "metrics/vcd_timescale.hpp"

namespace cnc::metrics {

namespace {

const char* const kWhere = "write_vcd";

// Short identifiers from the printable ASCII range '!'..'~', as VCD writers use.
std::string vcd_id(std::size_t n) {
    constexpr std::size_t kBase = '~' - '!' + 1;
    std::string id;
    do {
        id += static_cast<char>('!' + n % kBase);
        n /= kBase;
    } while (n > 0);
    return id;
}

struct Change {
    TimePs t_ps;
    std::size_t log;
    bool level;
};

void check_log(const EdgeLog& log, TimePs timescale_ps, std::set<std::string>& names) {
    const bool has_space = std::any_of(log.name.begin(), log.name.end(),
                                   [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; });
    if (log.name.empty() || has_space) {
        throw BadInput(kWhere, "signal name '" + log.name + "' is empty or contains white space");
    }
    if (!names.insert(log.name).second) throw BadInput(kWhere, "signal '" + log.name + "' given twice");
    TimePs previous = 0;
    for (const Edge& e : log.edges) {
        if (e.t_ps < previous) {
            throw BadInput(kWhere, "signal '" + log.name + "': edge at " + std::to_string(e.t_ps) +
                                       " ps is negative or out of time order");
        }
        if (e.t_ps % timescale_ps != 0) {
            throw BadInput(kWhere, "signal '" + log.name + "': edge at " + std::to_string(e.t_ps) +
                                       " ps is not a multiple of the timescale (" + std::to_string(timescale_ps) +
                                       " ps)");
        }
        previous = e.t_ps;
    }
}

}  // namespace

void write_vcd(std::ostream& out, const std::vector<EdgeLog>& logs, TimePs timescale_ps) {
    const std::optional<std::string> timescale = format_vcd_timescale(timescale_ps);
    if (!timescale) {
        throw BadInput(kWhere, "timescale " + std::to_string(timescale_ps) + " ps is not 1, 10 or 100 of ps .. s");
    }
    std::set<std::string> names;
    std::vector<Change> changes;
    for (std::size_t i = 0; i < logs.size(); ++i) {
        check_log(logs[i], timescale_ps, names);
        for (const Edge& e : logs[i].edges) changes.push_back({e.t_ps, i, e.level});
    }
    // Stable: changes at one instant keep their order within a log (a zero-width glitch stays a glitch).
    std::stable_sort(changes.begin(), changes.end(), [](const Change& a, const Change& b) { return a.t_ps < b.t_ps; });

    out << "$timescale " << *timescale << " $end\n$scope module cncsim $end\n";
    for (std::size_t i = 0; i < logs.size(); ++i) {
        out << "$var wire 1 " << vcd_id(i) << ' ' << logs[i].name << " $end\n";
    }
    out << "$upscope $end\n$enddefinitions $end\n#0\n$dumpvars\n";
    for (std::size_t i = 0; i < logs.size(); ++i) out << (logs[i].initial ? '1' : '0') << vcd_id(i) << '\n';
    out << "$end\n";
    TimePs now = 0;
    for (const Change& c : changes) {
        if (c.t_ps != now) {
            now = c.t_ps;
            out << '#' << now / timescale_ps << '\n';
        }
        out << (c.level ? '1' : '0') << vcd_id(c.log) << '\n';
    }
}

}  // namespace cnc::metrics
