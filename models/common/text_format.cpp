#include "common/text_format.hpp"

#include <cstdio>

namespace cnc {

std::string format(const char* fmt, double a, double b, double c, double d) {
    const int n = std::snprintf(nullptr, 0, fmt, a, b, c, d);
    std::string text(n > 0 ? static_cast<std::size_t>(n) : 0U, '\0');
    std::snprintf(text.data(), text.size() + 1, fmt, a, b, c, d);
    return text;
}

}  // namespace cnc
