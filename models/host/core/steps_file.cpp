#include "host/core/steps_file.hpp"

#include <array>
#include <cmath>
#include <fstream>
#include <string_view>

#include "common/bad_input.hpp"
#include "host/core/text_number.hpp"

namespace cnc::host {

namespace {

constexpr std::size_t kColumns = 9;  // seed 000 App. A.2: the sender needs at least 9 columns
constexpr std::array<const char*, kColumns> kColumnNames = {"Segment", "GcodeLine", "Motion",   "DX_mm",   "DY_mm",
                                                            "StepsX",  "StepsY",    "PathFeed", "FeedRate"};
constexpr std::int64_t kInt32Min = -2147483648LL;  // seed 000 §4.8
constexpr std::int64_t kInt32Max = 2147483647LL;
constexpr double kMaxFeed = 65535.0;  // seed 000 §4.8: uint16

std::vector<std::string_view> split_commas(std::string_view line) {
    std::vector<std::string_view> fields;
    for (;;) {
        const auto comma = line.find(',');
        fields.push_back(trim(line.substr(0, comma)));
        if (comma == std::string_view::npos) return fields;
        line.remove_prefix(comma + 1);
    }
}

class RowReader {
public:
    RowReader(std::vector<std::string_view> fields, std::string where)
        : m_fields(std::move(fields)), m_where(std::move(where)) {}

    std::int64_t integer(std::size_t col, std::int64_t min, std::int64_t max, const char* allowed) const {
        const auto v = parse_int(m_fields[col]);
        if (!v) fail(col, "is not an integer");
        if (*v < min || *v > max) fail(col, std::string("outside ") + allowed);
        return *v;
    }

    double number(std::size_t col) const {
        const auto v = parse_double(m_fields[col]);
        if (!v) fail(col, "is not a finite number");
        return *v;
    }

    [[noreturn]] void fail(std::size_t col, const std::string& what) const {
        throw BadInput(m_where, "column " + std::to_string(col) + " (" + kColumnNames[col] + ") '" +
                                    std::string(m_fields[col]) + "' " + what);
    }

private:
    std::vector<std::string_view> m_fields;
    std::string m_where;
};

MotionSegment parse_row(std::string_view line, const std::string& where) {
    std::vector<std::string_view> fields = split_commas(line);
    if (fields.size() < kColumns) {
        throw BadInput(where, std::to_string(fields.size()) + " columns, at least 9 needed (" + kStepsFileHeader + ")");
    }
    const RowReader row(std::move(fields), where);
    MotionSegment seg;
    seg.index = static_cast<int>(row.integer(0, kInt32Min, kInt32Max, "int32"));
    seg.line = static_cast<int>(row.integer(1, 0, kInt32Max, "0..2147483647"));
    seg.motion = static_cast<MotionKind>(row.integer(2, 0, 3, "0..3 (0 G0, 1 G1, 2 G2, 3 G3)"));
    seg.dx_mm = row.number(3);
    seg.dy_mm = row.number(4);
    seg.steps_x = row.integer(5, kInt32Min, kInt32Max, "int32 (-2147483648..2147483647)");
    seg.steps_y = row.integer(6, kInt32Min, kInt32Max, "int32 (-2147483648..2147483647)");
    seg.path_feed_mm_per_min = row.number(7);
    // send_steps.py: int(round(float(x))); Python rounds halves to even, as nearbyint does in the default mode.
    const double feed = std::nearbyint(row.number(8));
    if (feed < 0.0 || feed > kMaxFeed) row.fail(8, "outside 0..65535 mm/min");
    seg.feed = static_cast<std::int64_t>(feed);
    seg.move = -1;
    return seg;
}

}  // namespace

void write_steps_file(std::ostream& out, const std::vector<MotionSegment>& segments) {
    out << kStepsFileHeader << '\n';
    for (const MotionSegment& s : segments) {
        out << s.index << ',' << s.line << ',' << static_cast<int>(s.motion) << ',' << format_double(s.dx_mm) << ','
            << format_double(s.dy_mm) << ',' << s.steps_x << ',' << s.steps_y << ','
            << format_double(s.path_feed_mm_per_min) << ',' << s.feed << '\n';
    }
}

void save_steps_file(const std::string& path, const std::vector<MotionSegment>& segments) {
    std::ofstream out(path);
    if (!out) throw BadInput(path, "cannot create steps file");
    write_steps_file(out, segments);
    out.flush();
    if (!out) throw BadInput(path, "write error");
}

std::vector<MotionSegment> read_steps_file(std::istream& in, const std::string& filename) {
    std::vector<MotionSegment> segments;
    std::string text;
    int line = 0;
    while (std::getline(in, text)) {
        if (++line == 1) {
            // send_steps.py skips line 1 unread (seed 000 App. A.2): a file without its header would lose a segment.
            if (parse_int(split_commas(trim(text)).front())) {
                throw BadInput(filename + ":1", std::string("a data row where the header belongs (") +
                                                    kStepsFileHeader +
                                                    "): the sender skips line 1, so this "
                                                    "segment would never be sent; add the header line");
            }
            continue;
        }
        const std::string_view row = trim(text);
        if (row.empty()) continue;
        segments.push_back(parse_row(row, filename + ":" + std::to_string(line)));
    }
    if (in.bad()) throw BadInput(filename, "read error after line " + std::to_string(line));
    return segments;
}

std::vector<MotionSegment> load_steps_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw BadInput(path, "cannot open steps file");
    return read_steps_file(in, path);
}

}  // namespace cnc::host
