// Seed 002's tuning mode (our firmware, models/avr/firmware/lathe_sync/tuning.c) on the ATmega16
// model, driving the derived motor (models/lathe/core/dc_motor.hpp) through the L298: the period record it writes
// to EEPROM against the seed's decoded dump (§4.3).
//
// Time unit: the model's ATmega16 CTC gives (OCR2 + 1) x 32 / 8 MHz per count, and that is what the
// record's counts mean here (at the final OCR2 the firmware stored). The seed's dump is read with the author's
// unit (§4.3), OCR2 x 32 / F = 12 us at its OCR2 = 3: 39 counts = 468 us per motor pulse (2136.75 pulses/s), the
// figure the identified model G(s) and our motor derive from. So the record's steady state must be 468 us within
// 5 %, and its speed must rise with the pole -74.29 s^-1 within 5 %. (In this run the retries end at OCR2 = 2,
// whose hardware unit is 12 us: the record then reads as the seed's dump does, count for count.)
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "lathe_bench.hpp"

namespace {

using namespace cnc::lathe::test;

TEST(LatheTuning, PeriodRecordMatchesTheSeedsDump) {
    LatheBench b;
    b.hold('B', 0.05);  // held at power-up (§2.5.3), released after 50 ms
    // Three overflowing tries (OCR2 = 0, 1, 2) and the good one, each followed by a 500 ms brake and a 1 s wait,
    // then 401 EEPROM bytes of 8.5 ms at most: well inside 12 s.
    std::vector<std::uint8_t> ee;
    while (b.chip.cycle() < static_cast<Cycle>(12 * 8e6)) {
        for (int k = 0; k < 100'000; ++k) b.step();
        ee = b.chip.eeprom();
        if (ee.size() > 419 && ee[419] != 0xFF) break;
    }
    ASSERT_GT(ee.size(), 419U);
    const double unit_s = (ee[18] + 1) * 32 * kCycleS;  // the hardware CTC period at the final OCR2
    std::vector<double> period_s;
    for (int i = 20; i < 420; ++i) period_s.push_back(ee[static_cast<std::size_t>(i)] * unit_s);
    // The rise, entry by entry, against the seed's decoded dump (§4.3, line 0x010 from byte 21 on; byte 20, the
    // first period, depends on where the disc stopped): 122 100 88 80 75 72 68 66 64 62 counts of the author's
    // 12 us. The retries leave the disc elsewhere in each run, so the second entry is skipped too.
    const double seed_counts[] = {122, 100, 88, 80, 75, 72, 68, 66, 64, 62};
    for (std::size_t k = 0; k < std::size(seed_counts); ++k) {
        EXPECT_NEAR(period_s[k + 2], seed_counts[k] * 12e-6, 0.05 * seed_counts[k] * 12e-6) << "entry " << k + 2;
    }
    // Steady state: the last 200 periods.
    const double steady_s = std::accumulate(period_s.end() - 200, period_s.end(), 0.0) / 200.0;
    EXPECT_NEAR(steady_s, 39 * 12e-6, 0.05 * 39 * 12e-6);
    // Speed v = 1 / period at the middle of each period; fit log(v_inf - v) = log(a) - p t over the samples that
    // are more than 15 % below steady (above the +-1 count quantisation), skipping the first (arbitrary start).
    const double v_inf = 1.0 / steady_s;
    double t = period_s[0];
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t k = 1; k < period_s.size(); ++k) {
        const double mid = t + 0.5 * period_s[k];
        t += period_s[k];
        const double v = 1.0 / period_s[k];
        if (v_inf - v < 0.15 * v_inf) break;
        const double y = std::log(v_inf - v);
        sx += mid;
        sy += y;
        sxx += mid * mid;
        sxy += mid * y;
        ++n;
    }
    ASSERT_GE(n, 5);
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    EXPECT_NEAR(-slope, 74.29, 0.05 * 74.29);
}

}  // namespace
