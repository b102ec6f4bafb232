// Small accumulators shared by the metric families: maximum magnitude and RMS, worst signed value.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

namespace cnc::metrics {

class MaxRms {
public:
    void add(double v) {
        m_max_abs = std::max(m_max_abs, std::fabs(v));
        m_sum_sq += static_cast<long double>(v) * v;
        ++m_count;
    }
    [[nodiscard]] std::size_t count() const { return m_count; }
    [[nodiscard]] std::optional<double> max_abs() const {
        return m_count == 0 ? std::nullopt : std::optional<double>(m_max_abs);
    }
    [[nodiscard]] std::optional<double> rms() const {
        if (m_count == 0) return std::nullopt;
        return static_cast<double>(std::sqrt(m_sum_sq / static_cast<long double>(m_count)));
    }

private:
    double m_max_abs = 0.0;
    long double m_sum_sq = 0.0L;
    std::size_t m_count = 0;
};

// Keeps the value of largest magnitude, with its sign (a rate or feed error reads better signed).
inline void keep_worst_signed(std::optional<double>& worst, std::optional<double> v) {
    if (v && (!worst || std::fabs(*v) > std::fabs(*worst))) worst = v;
}

inline void keep_max(std::optional<double>& acc, std::optional<double> v) {
    if (v && (!acc || *v > *acc)) acc = v;
}

}  // namespace cnc::metrics
