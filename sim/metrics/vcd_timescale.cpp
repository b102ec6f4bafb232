#include "metrics/vcd_timescale.hpp"

#include <array>
#include <utility>

namespace cnc::metrics {

namespace {

// Coarsest first, so that formatting picks the largest unit.
constexpr std::array<std::pair<const char*, TimePs>, 5> kUnits{{
    {"s", kPsPerSec}, {"ms", kPsPerMs}, {"us", kPsPerUs}, {"ns", kPsPerNs}, {"ps", 1}}};
constexpr std::array<TimePs, 3> kMultipliers{1, 10, 100};

}  // namespace

std::optional<TimePs> parse_vcd_timescale(const std::string& text) {
    std::string compact;
    for (const char c : text) {
        if (c != ' ' && c != '\t') compact += c;
    }
    const std::size_t digits_end = compact.find_first_not_of("0123456789");
    if (digits_end == 0 || digits_end == std::string::npos) return std::nullopt;
    const std::string number = compact.substr(0, digits_end);
    const std::string unit = compact.substr(digits_end);
    std::optional<TimePs> multiplier;
    for (const TimePs m : kMultipliers) {
        if (number == std::to_string(m)) multiplier = m;
    }
    if (!multiplier) return std::nullopt;
    for (const auto& [name, ps] : kUnits) {
        if (unit == name) return *multiplier * ps;
    }
    return std::nullopt;
}

std::optional<std::string> format_vcd_timescale(TimePs ps) {
    for (const auto& [name, unit_ps] : kUnits) {
        for (const TimePs m : kMultipliers) {
            if (m * unit_ps == ps) return std::to_string(m) + " " + name;
        }
    }
    return std::nullopt;
}

}  // namespace cnc::metrics
