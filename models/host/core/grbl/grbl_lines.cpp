#include "host/core/grbl/grbl_lines.hpp"

#include <cctype>

namespace cnc::host::grbl {

std::string stripped_line(std::string_view line) {
    std::string out;
    bool in_paren = false;
    for (const char c : line) {
        if (in_paren) {
            in_paren = c != ')';
        } else if (c == '(') {
            in_paren = true;
        } else if (c == ';') {
            break;
        } else if (std::isspace(static_cast<unsigned char>(c)) == 0) {
            out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
        }
    }
    return out;
}

std::vector<SendLine> lines_to_send(std::string_view text, const std::string& file) {
    std::vector<SendLine> out;
    std::size_t number = 0;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        ++number;
        std::string s = stripped_line(line);
        if (!s.empty()) out.push_back({std::move(s), file + ":" + std::to_string(number)});
    }
    return out;
}

}  // namespace cnc::host::grbl
