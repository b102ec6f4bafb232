#include "output/table_cells.hpp"

namespace cnc::sim {

std::string csv_quoted(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + '"';
}

std::string csv_field(const std::string& s) {
    return s.find_first_of(",\"\r\n") == std::string::npos ? s : csv_quoted(s);
}

std::string md_cell(const std::string& s) {
    std::string out;
    for (const char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

}  // namespace cnc::sim
