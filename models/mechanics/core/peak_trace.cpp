#include "mechanics/core/peak_trace.hpp"

#include <algorithm>

namespace cnc::mech {

void PeakTrace::add(TimePs t_ps, double value) {
    const TimePs start = t_ps - t_ps % m_bucket_ps;
    if (!m_buckets.empty() && m_buckets.back().start_ps == start) {
        m_buckets.back().peak = std::max(m_buckets.back().peak, value);
        return;
    }
    m_buckets.push_back({start, value});
    if (m_buckets.size() > kMaxBuckets) coarsen();
}

void PeakTrace::coarsen() {
    m_bucket_ps *= 2;
    std::vector<Bucket> merged;
    merged.reserve(m_buckets.size() / 2 + 1);
    for (const Bucket& b : m_buckets) {
        const TimePs start = b.start_ps - b.start_ps % m_bucket_ps;
        if (!merged.empty() && merged.back().start_ps == start) {
            merged.back().peak = std::max(merged.back().peak, b.peak);
        } else {
            merged.push_back({start, b.peak});
        }
    }
    m_buckets = std::move(merged);
    if (m_buckets.size() > kMaxBuckets) coarsen();
}

std::vector<std::pair<TimePs, double>> PeakTrace::points() const {
    std::vector<std::pair<TimePs, double>> out;
    out.reserve(m_buckets.size());
    for (const Bucket& b : m_buckets) out.emplace_back(b.start_ps, b.peak);
    return out;
}

}  // namespace cnc::mech
