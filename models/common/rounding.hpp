// Numbers for the JSON reports: rounded to the resolution they carry. (Text is formatted with fmt, checked at
// compile time: FMT_STRING.)
#pragma once

namespace cnc {

// v to the resolution it carries (1 / per_unit: per_unit = 1e3 keeps three decimals), so that the JSON writer
// prints a short decimal instead of a full double's 17 digits: dividing by the exact integer per_unit gives the
// double nearest that decimal.
double rounded(double v, double per_unit);

}  // namespace cnc
