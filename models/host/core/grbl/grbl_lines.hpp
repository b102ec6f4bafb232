// A G-code file as a sender streams it to grbl: each line without its comments and blanks, in upper case (grbl's
// stream.py: re.sub('\s|\(.*?\)', '', line).upper(); ';' starts a comment to the end of the line, as grbl reads
// it). Lines left empty are not sent.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace cnc::host::grbl {

struct SendLine {
    std::string text;   // without the line end
    std::string where;  // "file:line" of the G-code, or what else the line is ("$110 from machine.x...")
};

[[nodiscard]] std::string stripped_line(std::string_view line);

// The lines of `text` (the contents of `file`) to send, each named file:line.
[[nodiscard]] std::vector<SendLine> lines_to_send(std::string_view text, const std::string& file);

}  // namespace cnc::host::grbl
