// Strict, locale-independent number text shared by the G-code lexer and the steps file: the whole text must
// be the number (no trailing characters), so "12abc" is an error and not 12.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace cnc::host {

// Optional sign, then a decimal number (exponent allowed); nullopt if malformed or not finite.
std::optional<double> parse_double(std::string_view text);
// Optional sign, then decimal digits only; nullopt if malformed or outside int64.
std::optional<std::int64_t> parse_int(std::string_view text);
// Shortest text that reads back as exactly `value` ("10", "0.00625", "-31.4625").
std::string format_double(double value);
// `text` without leading and trailing spaces, tabs and carriage returns.
std::string_view trim(std::string_view text);

}  // namespace cnc::host
