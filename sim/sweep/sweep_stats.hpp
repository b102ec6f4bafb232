// The statistics of a metric across a sweep's seeds (summary.md): mean, min, max and the 95 % confidence interval
// of the mean, mean +- t(0.975, n - 1) s / sqrt(n) with s the sample standard deviation (Student's t: the seeds
// are a small sample of the random sources' draws).
#pragma once
#include <cstddef>
#include <vector>

namespace cnc::sim {

struct SeedStats {
    std::size_t n = 0;
    double mean = 0.0;
    double min = 0.0;
    double max = 0.0;
    double half_width_95 = 0.0;  // 0 for one value (no spread to estimate: shown as such)
};

// Of at least one value.
SeedStats seed_stats(const std::vector<double>& values);

// Student's t quantile t(0.975, dof), dof >= 1: tabulated to 30, then the Cornish-Fisher expansion around the
// normal quantile (within 1e-4 of the exact value there).
double t_975(std::size_t dof);

}  // namespace cnc::sim
