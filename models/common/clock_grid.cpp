#include "common/clock_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/bad_input.hpp"
#include "common/math_constants.hpp"
#include "common/splitmix64.hpp"

namespace cnc {

namespace {

constexpr double kMaxOffsetPpm = 1e5;

// The standard normal distribution at kQuantiles equally likely points (its quantiles at (i + 1/2) / kQuantiles): a
// draw is one table entry picked by the hash, so a jittered edge costs one hash and a load, not a log and a cosine
// (a long lathe run asks for hundreds of millions of edges). The extreme entries sit at +-3.99 sigma.
constexpr int kQuantileBits = 14;
constexpr int kQuantiles = 1 << kQuantileBits;

double normal_cdf(double x) {
    return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

double normal_pdf(double x) {
    return std::exp(-0.5 * x * x) / std::sqrt(2.0 * kPi);
}

// The lower half by Newton's method on the CDF, each quantile started from the one before (three steps each, where
// a bisection takes eighty: the table is built on the first jittered edge of every run); the upper half by symmetry.
const std::vector<double>& normal_table() {
    static const std::vector<double> table = [] {
        std::vector<double> t(kQuantiles);
        double x = -kJitterCutSigmas;
        for (int i = 0; i < kQuantiles / 2; ++i) {
            const double p = (i + 0.5) / kQuantiles;
            for (int step = 0; step < 100; ++step) {
                const double dx = (normal_cdf(x) - p) / normal_pdf(x);
                x -= dx;
                if (std::fabs(dx) <= 1e-15 * std::max(1.0, std::fabs(x))) break;
            }
            t[static_cast<std::size_t>(i)] = x;
            t[static_cast<std::size_t>(kQuantiles - 1 - i)] = -x;
        }
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
    if (n == m_drawn_edge) return m_drawn_jitter_ps;
    const std::uint64_t key = splitmix64(m_seed ^ static_cast<std::uint64_t>(n));
    const double g = normal_table()[static_cast<std::size_t>(key >> (64 - kQuantileBits))];
    const double jitter = std::clamp(g, -kJitterCutSigmas, kJitterCutSigmas) * m_jitter_rms_ps;
    m_drawn_edge = n;
    m_drawn_jitter_ps = static_cast<TimePs>(jitter < 0.0 ? jitter - 0.5 : jitter + 0.5);  // nearest ps, as llround
    return m_drawn_jitter_ps;
}

TimePs ClockGrid::at(std::int64_t n) const {
    return cycles_to_ps(n, m_hz) + jitter_ps(n);
}

std::int64_t ClockGrid::last_at_or_before(TimePs t) const {
    if (t < 0) return -1;
    // The nominal edge at or before t, then at most one draw: the cut jitter is below a quarter period, so only the
    // nominal edge nearest t can land on the other side of it (most calls, away from the edges, need none).
    auto n = static_cast<std::int64_t>(static_cast<double>(t) * static_cast<double>(m_hz) * 1e-12);  // within one
    TimePs nominal_ps = cycles_to_ps(n, m_hz), next_nominal_ps = cycles_to_ps(n + 1, m_hz);
    for (; next_nominal_ps <= t; ++n) nominal_ps = std::exchange(next_nominal_ps, cycles_to_ps(n + 2, m_hz));
    for (; nominal_ps > t; --n) next_nominal_ps = std::exchange(nominal_ps, cycles_to_ps(n - 1, m_hz));
    const auto max_jitter_ps = static_cast<TimePs>(kJitterCutSigmas * m_jitter_rms_ps + 0.5);  // jitter_ps's bound
    if (t < nominal_ps + max_jitter_ps) return nominal_ps + jitter_ps(n) <= t ? n : n - 1;
    if (t >= next_nominal_ps - max_jitter_ps) return next_nominal_ps + jitter_ps(n + 1) <= t ? n + 1 : n;
    return n;
}

}  // namespace cnc
