// Splits one G-code line into words (letter + number). Comments "( ... )" and "; ..." are dropped, letters
// are case-insensitive and spaces outside comments are ignored everywhere, as in RS274/NGC ("G 0 1" = "G01").
#pragma once
#include <string>
#include <vector>

namespace cnc::host {

// Letters of the pseudo-words the lexer makes for what the interpreter does not evaluate: the rest of the
// line from a parameter '#' or an expression '[', and an O-word with a flow-control keyword ("O100CALL").
inline constexpr char kParameterWord = '#';
inline constexpr char kExpressionWord = '[';

struct GcodeWord {
    char letter;       // upper case, or kParameterWord / kExpressionWord
    double value;      // NaN for a pseudo-word and for an O-word with a keyword
    std::string text;  // as written, upper case and without spaces ("G01", "X-5."), for messages
};

// Throws cnc::BadInput(where, ...) for a letter without a number, a number without a letter, an
// unterminated or nested "(" comment or any other character.
std::vector<GcodeWord> lex_gcode_line(const std::string& line, const std::string& where);

}  // namespace cnc::host
