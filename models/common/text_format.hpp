// printf-style formatting of numbers for the reports' text (the project is C++17: no std::format).
#pragma once
#include <string>

namespace cnc {

// `fmt` takes up to four double conversions (%f, %e, %g; %.0f for counts).
std::string format(const char* fmt, double a, double b = 0.0, double c = 0.0, double d = 0.0);

}  // namespace cnc
