#include "lathe/core/thread_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace cnc::lathe {

namespace {

// The pulses of a pass that lie inside [from, to].
bool inside(const ThreadPass& p, std::size_t j, double from, double to) {
    return j < p.x_mm.size() && p.x_mm[j] >= from && p.x_mm[j] <= to;
}

}  // namespace

std::optional<double> phase_error_um(const std::vector<ThreadPass>& passes, std::size_t k, std::size_t j,
                                     const ThreadMetrics& m) {
    if (!inside(passes.front(), j, m.common_from_mm, m.common_to_mm) ||
        !inside(passes[k], j, m.common_from_mm, m.common_to_mm)) {
        return std::nullopt;
    }
    return (passes[k].x_mm[j] - passes.front().x_mm[j]) * 1000.0;
}

ThreadMetrics thread_metrics(const std::vector<ThreadPass>& passes, double pitch_mm, int pulses_per_rev,
                             int settle_revolutions) {
    ThreadMetrics m;
    if (passes.empty()) return m;
    m.common_from_mm = -INFINITY;
    m.common_to_mm = INFINITY;
    for (const ThreadPass& p : passes) {
        if (p.x_mm.empty()) return ThreadMetrics{};
        m.common_from_mm = std::max(m.common_from_mm, p.x_mm.front());
        m.common_to_mm = std::min(m.common_to_mm, p.x_mm.back());
    }
    const auto rev = static_cast<std::size_t>(pulses_per_rev);
    const std::size_t first_j = rev * static_cast<std::size_t>(settle_revolutions);
    double sum_um = 0.0;
    for (const ThreadPass& p : passes) {
        for (std::size_t j = first_j; j + rev < p.x_mm.size(); j += rev) {
            if (!inside(p, j, m.common_from_mm, m.common_to_mm) ||
                !inside(p, j + rev, m.common_from_mm, m.common_to_mm)) {
                continue;
            }
            const double e_um = (p.x_mm[j + rev] - p.x_mm[j] - pitch_mm) * 1000.0;
            sum_um += e_um;
            m.pitch_error_max_um = std::max(m.pitch_error_max_um, std::abs(e_um));
            ++m.revolutions;
        }
    }
    if (m.revolutions > 0) m.pitch_error_mean_um = sum_um / m.revolutions;
    double slope_sum_mm = 0.0;
    int fitted = 0;
    for (const ThreadPass& p : passes) {
        double n = 0.0, st = 0.0, sx = 0.0, stt = 0.0, stx = 0.0;
        for (std::size_t j = first_j; j < p.x_mm.size(); ++j) {
            if (!inside(p, j, m.common_from_mm, m.common_to_mm)) continue;
            const double t = static_cast<double>(j) / pulses_per_rev;
            n += 1.0;
            st += t;
            sx += p.x_mm[j];
            stt += t * t;
            stx += t * p.x_mm[j];
        }
        const double den = n * stt - st * st;
        if (n < 2.0 || den <= 0.0) continue;
        slope_sum_mm += (n * stx - st * sx) / den;
        ++fitted;
    }
    if (fitted > 0) m.pitch_fit_error_um = (slope_sum_mm / fitted - pitch_mm) * 1000.0;
    const ThreadPass& first = passes.front();
    for (std::size_t k = 1; k < passes.size(); ++k) {
        std::vector<double> d_um;
        for (std::size_t j = first_j; j < first.x_mm.size(); ++j) {
            const std::optional<double> d = phase_error_um(passes, k, j, m);
            if (!d) continue;
            d_um.push_back(*d);
            if (std::abs(d_um.back()) > m.phase_error_max_um) {
                m.phase_error_max_um = std::abs(d_um.back());
                m.phase_error_max_signed_um = d_um.back();
                m.phase_error_max_pass = k;
                m.phase_error_max_pulse = j;
            }
        }
        if (d_um.empty()) continue;
        const std::size_t n = std::min(d_um.size(), rev);
        double end_um = 0.0;
        for (std::size_t i = d_um.size() - n; i < d_um.size(); ++i) end_um += d_um[i];
        m.phase_error_end_um = std::max(m.phase_error_end_um, std::abs(end_um / static_cast<double>(n)));
    }
    return m;
}

}  // namespace cnc::lathe
