#include "metrics/vcd/vcd_timescale.hpp"

#include <array>
#include <cctype>
#include <limits>
#include <stdexcept>
#include <utility>

namespace cnc::metrics {

namespace {

constexpr std::int64_t kFsPerPs = 1'000;

// Coarsest first, so that formatting picks the largest unit.
constexpr std::array<std::pair<const char*, std::int64_t>, 6> kUnitsFs{{{"s", kPsPerSec* kFsPerPs},
                                                                        {"ms", kPsPerMs* kFsPerPs},
                                                                        {"us", kPsPerUs* kFsPerPs},
                                                                        {"ns", kPsPerNs* kFsPerPs},
                                                                        {"ps", kFsPerPs},
                                                                        {"fs", 1}}};
constexpr std::array<std::int64_t, 3> kMultipliersCoarsestFirst{100, 10, 1};

}  // namespace

std::optional<std::int64_t> parse_vcd_timescale_fs(const std::string& text) {
    std::string compact;
    for (const char c : text) {
        if (!std::isspace(static_cast<unsigned char>(c))) compact += c;
    }
    for (const auto& [unit, unit_fs] : kUnitsFs) {
        for (const std::int64_t m : kMultipliersCoarsestFirst) {
            if (compact == std::to_string(m) + unit) return m * unit_fs;
        }
    }
    return std::nullopt;
}

std::optional<std::string> format_vcd_timescale(std::int64_t timescale_fs) {
    for (const auto& [unit, unit_fs] : kUnitsFs) {
        for (const std::int64_t m : kMultipliersCoarsestFirst) {
            if (m * unit_fs == timescale_fs) return std::to_string(m) + " " + unit;
        }
    }
    return std::nullopt;
}

std::vector<std::string> vcd_timescale_names() {
    std::vector<std::string> names;
    for (const auto& [unit, unit_fs] : kUnitsFs) {
        for (const std::int64_t m : kMultipliersCoarsestFirst) names.push_back(std::to_string(m) + " " + unit);
    }
    return names;
}

std::optional<TimePs> vcd_ticks_to_ps(std::int64_t units, std::int64_t timescale_fs) {
    constexpr std::int64_t kMax = std::numeric_limits<TimePs>::max();
    if (timescale_fs >= kFsPerPs) {
        const std::int64_t tick_ps = timescale_fs / kFsPerPs;
        if (units > kMax / tick_ps) return std::nullopt;
        return units * tick_ps;
    }
    if (units > (kMax - kFsPerPs / 2) / timescale_fs) return std::nullopt;
    return (units * timescale_fs + kFsPerPs / 2) / kFsPerPs;
}

std::int64_t ps_to_vcd_ticks(TimePs t_ps, std::int64_t timescale_fs) {
    if (timescale_fs >= kFsPerPs) {
        const std::int64_t tick_ps = timescale_fs / kFsPerPs;
        return (t_ps + tick_ps / 2) / tick_ps;
    }
    const std::int64_t ticks_per_ps = kFsPerPs / timescale_fs;
    if (t_ps > std::numeric_limits<std::int64_t>::max() / ticks_per_ps) {
        throw std::overflow_error("VCD time " + std::to_string(t_ps) + " ps does not fit 64 bits in ticks of " +
                                  std::to_string(timescale_fs) + " fs");
    }
    return t_ps * ticks_per_ps;
}

bool on_vcd_tick(TimePs t_ps, std::int64_t timescale_fs) {
    return timescale_fs <= kFsPerPs || t_ps % (timescale_fs / kFsPerPs) == 0;
}

}  // namespace cnc::metrics
