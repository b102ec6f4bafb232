#include "cam/dxf_scan.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>

#include "common/bad_input.hpp"

namespace cnc::cam {

namespace {

constexpr int kEntityCode = 0;
constexpr int kNameCode = 2;
constexpr int kVariableCode = 9;
constexpr int kInsunitsValueCode = 70;

std::string trimmed(const std::string& s) {
    std::size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

bool parse_int(const std::string& text, int& value) {
    if (text.empty()) return false;
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (*end != '\0') return false;
    value = static_cast<int>(v);
    return true;
}

}  // namespace

DxfScan scan_dxf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw BadInput(path, "cannot open the drawing");
    const std::string not_dxf =
        "not a DXF drawing (an ASCII DXF file: lines of a group code, an integer, and its value)";
    DxfScan scan;
    std::string section, variable;
    bool seen_entities = false;
    int line = 0;
    for (std::string code_text; std::getline(in, code_text);) {
        ++line;
        const std::string code_line = trimmed(code_text);
        if (line == 1 && code_line.rfind("AutoCAD Binary DXF", 0) == 0) {
            throw BadInput(path, "a binary DXF: save the drawing as an ASCII DXF");
        }
        if (code_line.empty() && in.peek() == EOF) break;  // a last empty line
        int code = 0;
        if (!parse_int(code_line, code)) {
            throw BadInput(path + ":" + std::to_string(line), not_dxf + ", found '" + code_line.substr(0, 40) + "'");
        }
        std::string value_text;
        if (!std::getline(in, value_text)) {
            throw BadInput(path + ":" + std::to_string(line),
                           "the drawing ends inside a group: a code without its value");
        }
        ++line;
        const std::string value = trimmed(value_text);
        if (code == kEntityCode) {
            if (value == "SECTION" || value == "ENDSEC") section.clear();
            if (value == "EOF") break;
            if (section == "ENTITIES" && value != "VERTEX" && value != "SEQEND" && value != "ENDSEC") {
                scan.entities.push_back({value, line - 1});
            }
        } else if (code == kNameCode && section.empty()) {
            section = value;
            seen_entities = seen_entities || value == "ENTITIES";
        } else if (code == kVariableCode && section == "HEADER") {
            variable = value;
        } else if (code == kInsunitsValueCode && variable == "$INSUNITS") {
            if (!parse_int(value, scan.insunits)) {
                throw BadInput(path + ":" + std::to_string(line),
                               "$INSUNITS must be an integer, found '" + value + "'");
            }
            scan.insunits_line = line;
            variable.clear();
        }
    }
    if (!seen_entities) throw BadInput(path, not_dxf + ": it has no ENTITIES section");
    return scan;
}

}  // namespace cnc::cam
