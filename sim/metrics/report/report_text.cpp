// The report file's text. Laid out as nlohmann's dump(2) (two-space indent, "key": value, one member per line),
// except that an array of plain values (numbers, strings, booleans, null) is written on one line: a per-move
// column of a 40,000-move job is then one line of the file, not 40,000 indented ones. A member the json holds only
// as a placeholder (StreamedMember: the programmed moves' columns) is written from its source at its place.
#include <ostream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "metrics/metrics.hpp"
#include "metrics/report/report.hpp"

namespace cnc::metrics {

namespace {

using nlohmann::json;

bool one_line(const json& j) {
    if (!j.is_array() && !j.is_object()) return true;
    if (j.empty()) return true;
    if (j.is_object()) return false;
    for (const json& e : j) {
        if (e.is_array() || e.is_object()) return false;
    }
    return true;
}

void write(std::ostream& out, const json& j, int depth, const StreamedMember* member, std::size_t matched) {
    if (one_line(j)) {
        out << j.dump();
        return;
    }
    const std::string inner(static_cast<std::size_t>((depth + 1) * kReportIndent), ' ');
    out << (j.is_object() ? "{\n" : "[\n");
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
        if (!first) out << ",\n";
        first = false;
        out << inner;
        if (!j.is_object()) {
            write(out, it.value(), depth + 1, nullptr, 0);
            continue;
        }
        out << json(it.key()).dump() << ": ";
        const bool on_path = member != nullptr && matched < member->path.size() && it.key() == member->path[matched];
        if (on_path && matched + 1 == member->path.size()) {
            member->write(out, depth + 1);
        } else {
            write(out, it.value(), depth + 1, on_path ? member : nullptr, matched + 1);
        }
    }
    out << '\n' << std::string(static_cast<std::size_t>(depth * kReportIndent), ' ') << (j.is_object() ? '}' : ']');
}

}  // namespace

void write_report_text(std::ostream& out, const nlohmann::json& report, const StreamedMember* member) {
    write(out, report, 0, member, 0);
    out << '\n';
}

std::string report_text(const nlohmann::json& report) {
    std::ostringstream out;
    write_report_text(out, report);
    return out.str();
}

}  // namespace cnc::metrics
