#include "sweep/sweep_stats.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cnc::sim {

namespace {

// t(0.975, dof) for dof 1 .. 30 (any table of Student's t, e.g. NIST/SEMATECH e-Handbook of Statistical Methods
// §1.3.6.7.2), to 3 decimals.
constexpr double kT975[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                            2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                            2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
constexpr double kZ975 = 1.959963984540054;  // the normal distribution's 0.975 quantile

}  // namespace

double t_975(std::size_t dof) {
    if (dof == 0) throw std::invalid_argument("t quantile of 0 degrees of freedom");
    if (dof <= std::size(kT975)) return kT975[dof - 1];
    const double z = kZ975;
    const double n = static_cast<double>(dof);
    return z + (z * z * z + z) / (4.0 * n) + (5.0 * std::pow(z, 5) + 16.0 * z * z * z + 3.0 * z) / (96.0 * n * n);
}

SeedStats seed_stats(const std::vector<double>& values) {
    if (values.empty()) throw std::invalid_argument("statistics of no value");
    SeedStats s;
    s.n = values.size();
    s.min = *std::min_element(values.begin(), values.end());
    s.max = *std::max_element(values.begin(), values.end());
    double sum = 0.0;
    for (const double v : values) sum += v;
    s.mean = sum / static_cast<double>(s.n);
    if (s.n < 2) return s;
    double squares = 0.0;
    for (const double v : values) squares += (v - s.mean) * (v - s.mean);
    const double sd = std::sqrt(squares / static_cast<double>(s.n - 1));
    s.half_width_95 = t_975(s.n - 1) * sd / std::sqrt(static_cast<double>(s.n));
    return s;
}

}  // namespace cnc::sim
