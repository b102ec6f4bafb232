// Wake-up latency of the host's servo thread (not measured in the seed 004 thesis; use the LinuxCNC /
// Machinekit typical figures). Wake-up n happens at n * period + L_n, L_n drawn from a bounded distribution with
// an explicit, seeded PRNG (splitmix64, Steele et al. 2014) and our own inverse CDF: std::*_distribution differ
// between standard libraries, which would make a scenario's numbers depend on the compiler.
//
// Distributions (max = latency_max):
//   Exponential (default): an exponential of scale max/5 truncated at max, F(x) = (1 - e^(-x/b)) / (1 - e^(-max/b)).
//                cyclictest histograms on PREEMPT_RT are a sharp peak of a few us with a thin tail: most wake-ups
//                are close to on time and about 1 % of them lie in the last fifth before the bound
//                (P(L > 0.8 max) = (e^-4 - e^-5) / (1 - e^-5) = 1.16 %), so the bound is reached in any run of
//                more than a few hundred periods. Mean 0.19 max.
//   Uniform:     U[0, max]: every latency up to the bound equally likely (a pessimistic, flat jitter). Mean max/2.
// The default bound, 50 us, is the LinuxCNC latency-test limit up to which "software stepping is OK"
// (docs/src/install/latency-test.adoc: max jitter < 20 us good, 20-50 us OK) and a common
// PREEMPT_RT Raspberry Pi 3 figure. max = 0 gives exact wake-ups. Latencies are whole nanoseconds.
#pragma once
#include <cstdint>
#include <string>

#include "common/units.hpp"

namespace cnc::host::servo {

enum class LatencyDistribution { Exponential, Uniform };

// The exponential's scale as a fraction of the bound (see above).
inline constexpr double kExponentialScaleOfMax = 0.2;

struct LatencyConfig {
    LatencyDistribution distribution = LatencyDistribution::Exponential;
    TimePs max_ps = 50 * kPsPerUs;
};

[[nodiscard]] LatencyDistribution latency_distribution_from(const std::string& name);  // "exponential" | "uniform"
[[nodiscard]] const char* to_string(LatencyDistribution d);

// splitmix64 (public domain reference by S. Vigna): 64-bit state, full period, passes BigCrush; enough for
// latency draws and identical on every platform.
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : m_state(seed) {}
    std::uint64_t next();
    // Uniform in [0, 1) with 53 random bits.
    double next_unit();

private:
    std::uint64_t m_state;
};

// The quantile of the configured distribution at u in [0, 1), in ps rounded to whole ns, within [0, max_ps].
[[nodiscard]] TimePs latency_quantile(const LatencyConfig& cfg, double u);

class LatencyGenerator {
public:
    // Streams for different seeds are independent; the seed is mixed so that seed 0 works too.
    LatencyGenerator(const LatencyConfig& cfg, std::uint64_t seed);
    TimePs next();

private:
    LatencyConfig m_cfg;
    SplitMix64 m_rng;
};

}  // namespace cnc::host::servo
