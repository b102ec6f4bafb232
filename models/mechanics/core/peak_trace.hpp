// The largest value of a quantity per time bucket, in bounded memory: when the buckets would exceed
// kMaxBuckets, neighbours merge and the bucket width doubles. A job of hours keeps a trace of the same size as
// one of seconds (what a plot of the load angle over time needs: its peaks, not every integration step).
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "common/units.hpp"

namespace cnc::mech {

class PeakTrace {
public:
    static constexpr std::size_t kMaxBuckets = 2048;

    explicit PeakTrace(TimePs bucket_ps = kPsPerMs) : m_bucket_ps(bucket_ps) {}

    // t_ps never decreases between calls.
    void add(TimePs t_ps, double value);

    // (bucket start, largest value in it), buckets in time order; empty buckets are left out.
    [[nodiscard]] std::vector<std::pair<TimePs, double>> points() const;
    [[nodiscard]] TimePs bucket_ps() const { return m_bucket_ps; }

private:
    struct Bucket {
        TimePs start_ps = 0;
        double peak = 0.0;
    };
    void coarsen();

    TimePs m_bucket_ps;
    std::vector<Bucket> m_buckets;
};

}  // namespace cnc::mech
