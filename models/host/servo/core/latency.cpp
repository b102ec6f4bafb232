#include "host/servo/core/latency.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cnc::host::servo {

namespace {
// Keeps the latency stream apart from any other consumer of the scenario seed (an arbitrary odd constant).
constexpr std::uint64_t kLatencyStream = 0x6C61'7465'6E63'7931ULL;  // "latency1"
}  // namespace

LatencyDistribution latency_distribution_from(const std::string& name) {
    if (name == "exponential") return LatencyDistribution::Exponential;
    if (name == "uniform") return LatencyDistribution::Uniform;
    throw std::invalid_argument("unknown latency distribution '" + name + "'");
}

const char* to_string(LatencyDistribution d) {
    return d == LatencyDistribution::Exponential ? "exponential" : "uniform";
}

std::uint64_t SplitMix64::next() {
    std::uint64_t z = (m_state += 0x9E37'79B9'7F4A'7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58'476D'1CE4'E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D0'49BB'1331'11EBULL;
    return z ^ (z >> 31);
}

double SplitMix64::next_unit() {
    return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

TimePs latency_quantile(const LatencyConfig& cfg, double u) {
    if (cfg.max_ps <= 0) return 0;
    const double max_ns = static_cast<double>(cfg.max_ps) / static_cast<double>(kPsPerNs);
    double x_ns = 0.0;
    if (cfg.distribution == LatencyDistribution::Uniform) {
        x_ns = u * max_ns;
    } else {
        const double scale_ns = kExponentialScaleOfMax * max_ns;
        // Inverse of F(x) = (1 - e^(-x/b)) / (1 - e^(-max/b)); expm1/log1p keep small u exact.
        x_ns = -scale_ns * std::log1p(u * std::expm1(-max_ns / scale_ns));
    }
    const auto ns = static_cast<TimePs>(std::llround(std::clamp(x_ns, 0.0, max_ns)));
    return std::min(ns * kPsPerNs, cfg.max_ps);
}

LatencyGenerator::LatencyGenerator(const LatencyConfig& cfg, std::uint64_t seed)
    : m_cfg(cfg), m_rng(seed ^ kLatencyStream) {}

TimePs LatencyGenerator::next() {
    return latency_quantile(m_cfg, m_rng.next_unit());
}

}  // namespace cnc::host::servo
