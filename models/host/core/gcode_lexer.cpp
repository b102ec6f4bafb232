#include "host/core/gcode_lexer.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "common/bad_input.hpp"
#include "host/core/text_number.hpp"

namespace cnc::host {

namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

bool is_number_char(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-';
}
bool is_alpha(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) != 0;
}
char upper(char c) {
    return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
}

bool is_digit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// G-code numbers have no exponent: "X1e5" is X1 followed by the word E5. Written as an exponent, a number beyond
// a double ("X1e400") is what the author meant and is refused as out of range, not blamed on an E word.
void check_exponent_range(const std::string& line, std::size_t e_at, const std::string& where) {
    if (e_at == 0 || !(is_digit(line[e_at - 1]) || line[e_at - 1] == '.')) return;
    std::size_t end = e_at + 1;
    if (end < line.size() && (line[end] == '+' || line[end] == '-')) ++end;
    if (end >= line.size() || !is_digit(line[end])) return;
    while (end < line.size() && is_digit(line[end])) ++end;
    std::size_t start = e_at;
    while (start > 0 && (is_digit(line[start - 1]) || line[start - 1] == '.')) --start;
    if (start > 0 && (line[start - 1] == '+' || line[start - 1] == '-')) --start;
    const std::string number = line.substr(start, end - start);
    errno = 0;
    const double v = std::strtod(number.c_str(), nullptr);
    if (errno == ERANGE || !std::isfinite(v)) {
        throw BadInput(where, "number '" + number +
                                  "' is out of range (G-code numbers have no exponent; this one "
                                  "is beyond what a double holds, 1.8e308, or below its smallest)");
    }
}

// Line text with the comments and spaces removed, so that numbers may contain spaces as RS274/NGC allows.
// RS274/NGC comments do not nest: a '(' inside one is an error rather than a guess at what was meant.
std::string strip_comments_and_spaces(const std::string& line, const std::string& where) {
    std::string out;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == ';') break;
        if (c == '(') {
            const auto close = line.find(')', i);
            const auto inner = line.find('(', i + 1);
            if (inner != std::string::npos && (close == std::string::npos || inner < close)) {
                throw BadInput(where, "nested comment: '(' inside a comment (G-code comments do not nest)");
            }
            if (close == std::string::npos) throw BadInput(where, "unterminated comment: '(' without ')'");
            i = close;
        } else if (!std::isspace(static_cast<unsigned char>(c))) {
            if (c == 'e' || c == 'E') check_exponent_range(line, i, where);
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
        if (c == kParameterWord || c == kExpressionWord) {
            words.push_back(GcodeWord{c, kNoValue, text.substr(i)});
            break;
        }
        std::size_t end = i + 1;
        while (end < text.size() && is_number_char(text[end])) ++end;
        if (is_alpha(c)) {
            const char letter = upper(c);
            const std::string number = text.substr(i + 1, end - i - 1);
            if (number.empty() && end < text.size() && (text[end] == kParameterWord || text[end] == kExpressionWord)) {
                words.push_back(GcodeWord{text[end], kNoValue, text.substr(i)});  // "X#1", "F[100+200]"
                break;
            }
            if (number.empty()) throw BadInput(where, std::string("word '") + letter + "' has no number");
            if (!is_gcode_number(number)) {
                throw BadInput(where, std::string("word '") + letter + number + "' has a malformed number");
            }
            const auto value = parse_double(number);
            if (!value) {
                throw BadInput(where, std::string("word '") + letter + number +
                                          "': the number is out of range (beyond what a double holds, 1.8e308)");
            }
            std::string word = letter + number;
            if (letter == 'O' && end < text.size() && is_alpha(text[end])) {
                // LinuxCNC O-word flow control ("o100 sub", "o101 if [...]"): the keyword joins the word.
                while (end < text.size() && is_alpha(text[end])) word.push_back(upper(text[end++]));
                words.push_back(GcodeWord{letter, kNoValue, word});
                break;
            }
            words.push_back(GcodeWord{letter, *value, word});
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
