// The report file's text. Laid out as nlohmann's dump(2) (two-space indent, "key": value, one member per line),
// except that an array of plain values (numbers, strings, booleans, null) is written on one line: a per-move
// column of a 40,000-move job is then one line of the file, not 40,000 indented ones.
#include <string>

#include "metrics/metrics.hpp"

namespace cnc::metrics {

namespace {

using nlohmann::json;

constexpr int kIndent = 2;

bool one_line(const json& j) {
    if (!j.is_array() && !j.is_object()) return true;
    if (j.empty()) return true;
    if (j.is_object()) return false;
    for (const json& e : j) {
        if (e.is_array() || e.is_object()) return false;
    }
    return true;
}

void write(std::string& out, const json& j, int depth) {
    if (one_line(j)) {
        out += j.dump();
        return;
    }
    const std::string inner(static_cast<std::size_t>((depth + 1) * kIndent), ' ');
    out += j.is_object() ? "{\n" : "[\n";
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
        if (!first) out += ",\n";
        first = false;
        out += inner;
        if (j.is_object()) out += json(it.key()).dump() + ": ";
        write(out, it.value(), depth + 1);
    }
    out += '\n' + std::string(static_cast<std::size_t>(depth * kIndent), ' ') + (j.is_object() ? '}' : ']');
}

}  // namespace

std::string report_text(const nlohmann::json& report) {
    std::string out;
    write(out, report, 0);
    return out + '\n';
}

}  // namespace cnc::metrics
