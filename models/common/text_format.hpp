// Numbers for the reports: printf-style formatting for the text (the project is C++17: no std::format), and
// rounding for the JSON.
#pragma once
#include <string>

namespace cnc {

// `fmt` takes up to four double conversions (%f, %e, %g; %.0f for counts).
std::string format(const char* fmt, double a, double b = 0.0, double c = 0.0, double d = 0.0);

// v to the resolution it carries (1 / per_unit: per_unit = 1e3 keeps three decimals), so that the JSON writer
// prints a short decimal instead of a full double's 17 digits: dividing by the exact integer per_unit gives the
// double nearest that decimal.
double rounded(double v, double per_unit);

}  // namespace cnc
