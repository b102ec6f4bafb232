#include "common/clock_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/bad_input.hpp"
#include "common/splitmix64.hpp"

namespace cnc {

namespace {

constexpr double kMaxOffsetPpm = 1e5;

// The standard normal distribution at kQuantiles equally likely points (its quantiles at (i + 1/2) / kQuantiles): a
// draw is one table entry picked by the hash, so a jittered edge costs one hash and a load, not a log and a cosine
// (a long lathe run asks for hundreds of millions of edges). The extreme entries sit at +-3.99 sigma.
constexpr int kQuantileBits = 14;
constexpr int kQuantiles = 1 << kQuantileBits;

double normal_quantile(double p) {
    double lo = -10.0, hi = 10.0;  // bisection on the normal CDF, 0.5 erfc(-x / sqrt 2)
    for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (lo + hi);
        (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

const std::vector<double>& normal_table() {
    static const std::vector<double> table = [] {
        std::vector<double> t(kQuantiles);
        for (int i = 0; i < kQuantiles; ++i) t[static_cast<std::size_t>(i)] = normal_quantile((i + 0.5) / kQuantiles);
        return t;
    }();
    return table;
}

}  // namespace

ClockGrid::ClockGrid(std::int64_t nominal_hz, const ClockDeviation& d, const char* where)
    : m_nominal_hz(nominal_hz), m_hz(0), m_jitter_rms_ps(d.jitter_rms_ps), m_seed(d.seed) {
    if (nominal_hz <= 0 || nominal_hz >= 1'000'000'000) {
        throw BadInput(where, "the clock frequency must be above 0 Hz and below 1 GHz");
    }
    if (!std::isfinite(d.offset_ppm) || std::fabs(d.offset_ppm) > kMaxOffsetPpm) {
        throw BadInput(
            where, "the clock offset must be within +-100000 ppm (10 %), not " + std::to_string(d.offset_ppm) + " ppm");
    }
    m_hz = std::llround(static_cast<long double>(nominal_hz) * (1.0L + static_cast<long double>(d.offset_ppm) * 1e-6L));
    const double period_ps = 1e12 / static_cast<double>(m_hz);
    if (!std::isfinite(d.jitter_rms_ps) || d.jitter_rms_ps < 0.0 ||
        kJitterCutSigmas * d.jitter_rms_ps >= period_ps / 4.0) {
        throw BadInput(where, "the clock's rms jitter must be >= 0 ps and below a sixteenth of its period (" +
                                  std::to_string(period_ps / (4.0 * kJitterCutSigmas)) + " ps), not " +
                                  std::to_string(d.jitter_rms_ps) + " ps");
    }
}

double ClockGrid::offset_ppm() const {
    return static_cast<double>(m_hz - m_nominal_hz) / static_cast<double>(m_nominal_hz) * 1e6;
}

std::int64_t ClockGrid::grid_hz() const {
    return m_jitter_rms_ps > 0.0 || kPsPerSec % m_hz != 0 ? kPsPerSec : m_hz;
}

TimePs ClockGrid::jitter_ps(std::int64_t n) const {
    if (m_jitter_rms_ps <= 0.0 || n == 0) return 0;  // edge 0 is the time origin of the clocked logic
    const std::uint64_t key = splitmix64(m_seed ^ static_cast<std::uint64_t>(n));
    const double g = normal_table()[static_cast<std::size_t>(key >> (64 - kQuantileBits))];
    return static_cast<TimePs>(std::llround(std::clamp(g, -kJitterCutSigmas, kJitterCutSigmas) * m_jitter_rms_ps));
}

TimePs ClockGrid::at(std::int64_t n) const {
    return cycles_to_ps(n, m_hz) + jitter_ps(n);
}

std::int64_t ClockGrid::last_at_or_before(TimePs t) const {
    if (t < 0) return -1;
    auto n = static_cast<std::int64_t>(
        std::floor(static_cast<long double>(t) * static_cast<long double>(m_hz) / static_cast<long double>(kPsPerSec)));
    while (at(n + 1) <= t) ++n;
    while (n >= 0 && at(n) > t) --n;
    return n;
}

bool ClockGrid::is_edge(TimePs t) const {
    const std::int64_t n = last_at_or_before(t);
    return n >= 0 && at(n) == t;
}

}  // namespace cnc
