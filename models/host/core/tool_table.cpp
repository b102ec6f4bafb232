#include "host/core/tool_table.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/bad_input.hpp"
#include "host/core/text_number.hpp"

namespace cnc::host {

namespace {

// Every letter of a LinuxCNC tool-table line (tooldata_read_entry): T tool, P pocket, D diameter, X Y Z A B C
// U V W offsets, I J front and back angle, Q orientation (lathe tools). cncsim uses T, P, D and Z; the others
// are read and have no effect (a desktop XY machine has neither lathe tools nor tool offsets off the Z axis).
constexpr const char* kLetters = "TPDXYZABCUVWIJQ";
constexpr const char* kAllowed =
    "a line is words T<tool> P<pocket> D<diameter mm> Z<length offset mm> (also X Y A B C U V W I J Q, read and "
    "not used), each a letter and its number without a space, then an optional ';' comment; T is a whole number "
    ">= 1, P a whole number >= 0, once each per line";
// LinuxCNC's tool numbers are C ints; a bound far above any desktop changer keeps them there.
constexpr double kMaxToolNumber = 99999.0;

int whole_number(const std::string& word, double v, double min, const std::string& where) {
    if (v != std::floor(v) || v < min || v > kMaxToolNumber) {
        throw BadInput(where, "'" + word + "' must be a whole number " + format_double(min) + " .. " +
                                  format_double(kMaxToolNumber) + " (" + kAllowed + ")");
    }
    return static_cast<int>(v);
}

}  // namespace

const ToolEntry* ToolTable::find(int tool) const {
    static const ToolEntry kNoTool{};
    if (tool == 0) return &kNoTool;
    const auto it = m_tools.find(tool);
    return it == m_tools.end() ? nullptr : &it->second;
}

ToolTable ToolTable::parse(std::istream& in, const std::string& filename) {
    ToolTable table;
    table.m_file = filename;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        const std::string where = filename + ":" + std::to_string(line);
        const std::string body(trim(text.substr(0, text.find(';'))));
        if (body.empty()) continue;
        std::istringstream words(body);
        ToolEntry e;
        e.line = line;
        std::string seen;
        for (std::string w; words >> w;) {
            const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(w.front())));
            if (std::string(kLetters).find(letter) == std::string::npos) {
                throw BadInput(where, "'" + w + "' is not a tool-table word (" + kAllowed + ")");
            }
            if (seen.find(letter) != std::string::npos) {
                throw BadInput(where, std::string("the letter ") + letter + " appears twice (" + kAllowed + ")");
            }
            seen += letter;
            const std::optional<double> v = parse_double(w.substr(1));
            if (!v) throw BadInput(where, "'" + w + "': the letter is not followed by a number (" + kAllowed + ")");
            if (letter == 'T') e.tool = whole_number(w, *v, 1.0, where);
            if (letter == 'P') e.pocket = whole_number(w, *v, 0.0, where);
            if (letter == 'D') e.diameter_mm = *v;
            if (letter == 'Z') e.z_offset_mm = *v;
        }
        if (seen.find('T') == std::string::npos) throw BadInput(where, std::string("no T word (") + kAllowed + ")");
        const auto [it, fresh] = table.m_tools.emplace(e.tool, e);
        if (!fresh) {
            throw BadInput(where, "tool " + std::to_string(e.tool) + " is already on line " +
                                      std::to_string(it->second.line) + ": one line per tool");
        }
    }
    if (in.bad()) throw BadInput(filename, "read error");
    return table;
}

ToolTable ToolTable::load(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw BadInput(path, "cannot open the tool table");
    return parse(in, path);
}

}  // namespace cnc::host
