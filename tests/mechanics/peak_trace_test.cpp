#include "mechanics/core/peak_trace.hpp"

#include <gtest/gtest.h>

namespace {

using cnc::TimePs;
using cnc::mech::PeakTrace;

// One value per 1 ms bucket keeps each bucket's largest value, at the bucket's start.
TEST(PeakTrace, KeepsTheLargestValueOfEachBucket) {
    PeakTrace t(1000);
    t.add(0, 1.0);
    t.add(400, 3.0);
    t.add(999, 2.0);
    t.add(2500, 5.0);
    const auto p = t.points();
    ASSERT_EQ(p.size(), 2U);
    EXPECT_EQ(p[0], (std::pair<TimePs, double>{0, 3.0}));
    EXPECT_EQ(p[1], (std::pair<TimePs, double>{2000, 5.0}));
}

// A ramp 0, 1, 2, ... at one value per bucket: past kMaxBuckets the width doubles as often as needed, the
// buckets stay within the bound, and each merged bucket holds the largest (the last) value of its span, so the
// overall peak and the final value survive every merge.
TEST(PeakTrace, StaysBoundedAndKeepsThePeaksOfALongRun) {
    PeakTrace t(1);
    const int n = 10 * static_cast<int>(PeakTrace::kMaxBuckets);
    for (int i = 0; i < n; ++i) t.add(i, static_cast<double>(i));
    const auto p = t.points();
    EXPECT_LE(p.size(), PeakTrace::kMaxBuckets);
    // 20480 one-ps values need a width of at least 20480 / 2048 = 10 ps; widths double from 1: 16 ps.
    EXPECT_EQ(t.bucket_ps(), 16);
    for (std::size_t k = 0; k < p.size(); ++k) {
        EXPECT_EQ(p[k].first % t.bucket_ps(), 0);
        const TimePs last_in_bucket = std::min<TimePs>(p[k].first + t.bucket_ps() - 1, n - 1);
        EXPECT_DOUBLE_EQ(p[k].second, static_cast<double>(last_in_bucket));
    }
    EXPECT_DOUBLE_EQ(p.back().second, n - 1.0);
}

}  // namespace
