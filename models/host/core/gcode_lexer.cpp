#include "host/core/gcode_lexer.hpp"

#include <cctype>

#include "common/bad_input.hpp"
#include "host/core/text_number.hpp"

namespace cnc::host {

namespace {

bool is_number_char(char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-'; }

// Line text with the comments and spaces removed, so that numbers may contain spaces as RS274/NGC allows.
std::string strip_comments_and_spaces(const std::string& line, const std::string& where) {
    std::string out;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == ';') break;
        if (c == '(') {
            const auto close = line.find(')', i);
            if (close == std::string::npos) throw BadInput(where, "unterminated comment: '(' without ')'");
            i = close;
        } else if (!std::isspace(static_cast<unsigned char>(c))) {
            out.push_back(c);
        }
    }
    return out;
}

// A G-code number: optional sign, then digits with at most one '.', at least one digit ("10", "-5.", ".5").
bool is_gcode_number(const std::string& text) {
    std::size_t i = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
    int digits = 0;
    int dots = 0;
    for (; i < text.size(); ++i) {
        if (text[i] == '.') {
            ++dots;
        } else if (std::isdigit(static_cast<unsigned char>(text[i]))) {
            ++digits;
        } else {
            return false;
        }
    }
    return digits > 0 && dots <= 1;
}

}  // namespace

std::vector<GcodeWord> lex_gcode_line(const std::string& line, const std::string& where) {
    const std::string text = strip_comments_and_spaces(line, where);
    std::vector<GcodeWord> words;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        std::size_t end = i + 1;
        while (end < text.size() && is_number_char(text[end])) ++end;
        if (std::isalpha(static_cast<unsigned char>(c))) {
            const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
            const std::string number = text.substr(i + 1, end - i - 1);
            if (number.empty()) throw BadInput(where, std::string("word '") + letter + "' has no number");
            const auto value = parse_double(number);
            if (!is_gcode_number(number) || !value) {
                throw BadInput(where, std::string("word '") + letter + number + "' has a malformed number");
            }
            words.push_back(GcodeWord{letter, *value, letter + number});
        } else if (is_number_char(c)) {
            end = i;
            while (end < text.size() && is_number_char(text[end])) ++end;
            throw BadInput(where, "number '" + text.substr(i, end - i) + "' without a letter");
        } else {
            throw BadInput(where, std::string("unexpected character '") + c + "'");
        }
        i = end;
    }
    return words;
}

}  // namespace cnc::host
