// Splits one G-code line into words (letter + number). Comments "( ... )" and "; ..." are dropped, letters
// are case-insensitive and spaces outside comments are ignored everywhere, as in RS274/NGC ("G 0 1" = "G01").
#pragma once
#include <string>
#include <vector>

namespace cnc::host {

struct GcodeWord {
    char letter;       // upper case
    double value;
    std::string text;  // as written, upper case and without spaces ("G01", "X-5."), for messages
};

// Throws cnc::BadInput(where, ...) for a letter without a number, a number without a letter, an
// unterminated "(" comment or any other character.
std::vector<GcodeWord> lex_gcode_line(const std::string& line, const std::string& where);

}  // namespace cnc::host
