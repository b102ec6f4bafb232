#include "common/text_format.hpp"

#include <cmath>
#include <cstdio>

namespace cnc {

std::string format(const char* fmt, double a, double b, double c, double d) {
    const int n = std::snprintf(nullptr, 0, fmt, a, b, c, d);
    std::string text(n > 0 ? static_cast<std::size_t>(n) : 0U, '\0');
    std::snprintf(text.data(), text.size() + 1, fmt, a, b, c, d);
    return text;
}

double rounded(double v, double per_unit) {
    return std::round(v * per_unit) / per_unit;
}

}  // namespace cnc
