// The seed 002 firmware (our C, on the ATmega16 model) cutting an M6 thread (1.0 mm) as a
// machinist would key it in (§2.5.2): 1 (cut), 3 (thread), pitch 1#00 D, 1 (hand), length 10 D, then D to cut and
// D to retract, pass after pass. Thread metrics as docs/metrics.md "Lathe" (models/lathe/core/thread_metrics).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "lathe/core/thread_metrics.hpp"
#include "lathe_bench.hpp"

namespace {

using namespace cnc::lathe::test;
using cnc::lathe::ThreadMetrics;
using cnc::lathe::ThreadPass;

constexpr double kPulseUm = 3175.0 / 780.0;  // carriage per motor pulse (§2.5.3): 4.07 um

// cut_s after OK: the wait for the index (< 1 revolution), 10 revolutions, the 500 ms brake and the slip shown 1 s.
// retract_s: 10 mm at full then slow speed (< 2 s) and the brake.
void thread_m6(LatheBench& b, int passes_wanted, double cut_s, double retract_s = 3.0) {
    b.run_for(0.3);
    b.type("131#00D110D");
    for (int p = 0; p < passes_wanted; ++p) {
        b.press('D');  // press OK to cut
        b.run_for(cut_s);
        b.press('D');  // OK to retract
        b.run_for(retract_s);
    }
}

std::vector<ThreadPass> thread_passes(const LatheBench& b) {
    std::vector<ThreadPass> out;
    for (const cnc::lathe::RecordedPass& p : b.passes) out.push_back(p.thread);
    return out;
}

// Three passes of the M6 thread at `rpm`: 10 revolutions take 600 / rpm s, after up to 1 revolution waiting for
// the index, and the 500 ms brake and the slip shown 1 s follow.
std::vector<ThreadPass> three_passes(double rpm, const char* elf) {
    LatheBench b(rpm, elf);
    thread_m6(b, 3, 2.0 + 660.0 / rpm);
    EXPECT_EQ(b.passes.size(), 3U);
    return thread_passes(b);
}

ThreadMetrics m6_metrics(const std::vector<ThreadPass>& passes, int settle_revolutions = 0) {
    const ThreadMetrics m = cnc::lathe::thread_metrics(passes, 1.0, 40, settle_revolutions);
    // 10 mm asked (length_pulses = 780 x 1000 x 10 / 3175 = 2456 pulses, 9.997 mm): the passes cover it.
    EXPECT_NEAR(m.common_to_mm - m.common_from_mm, 9.97, 0.03);
    return m;
}

// With the pulse ISRs made atomic (seed option PULSE_ISR_ATOMIC, control.c), at 60 rpm, leaving out
// the first 2 revolutions of each pass: the passes end on one helix (the last common revolution within 2 motor
// pulses, 8.14 um, of pass 1) and the thread's mean pitch is within 0.1 % (1 um per revolution at 1 mm).
// What the seed's loop does not do, asserted so that the report's figures stay explained:
//   * Passes 2 and 3 start slip pulses (about 12) behind the helix (Error = slip, §2.5.1): the P term alone asks
//     2305 x 12 / 32 > 1023, full duty, and the output cannot go below 0 (§2.5.3's clamp) to brake, so the motor coasts
//     through the helix with its 13.5 ms time constant (§4.3) and rings down with the PID's slow pole (-1.17 s^-1,
//     from §4.3's model and gains): over the whole common length the passes differ by far more than 2 pulses.
//   * At 60 rpm the motor runs at 11 % duty and each B(n) (6 or 7 pulses every 25 ms) is a step the P and D terms
//     answer with a burst of full duty: the carriage is a few pulses off the helix at any one spindle pulse, so the
//     pitch error of single revolutions is tens of um; their mean over a 10-revolution pass carries the few pulses
//     at its two ends, hence the least-squares pitch over every pulse.
TEST(LatheThread, ThreePassesEndOnOneHelix) {
    const std::vector<ThreadPass> passes = three_passes(60.0, LATHE_SYNC_ATOMIC_ELF);
    const ThreadMetrics m = m6_metrics(passes, 2);
    EXPECT_LT(m.phase_error_end_um, 2 * kPulseUm);
    EXPECT_LT(std::abs(m.pitch_fit_error_um), 1.0);
    EXPECT_GT(m.pitch_error_max_um, 2 * kPulseUm);
    EXPECT_GT(m6_metrics(passes).phase_error_max_um, 5 * kPulseUm);
}

// The seed's nested pulse ISRs (every ISR ISR_NOBLOCK, §2.5.3) at 200 rpm: INT1 preempting INT0's ls_pulses++ makes
// Error lose a whole interval's pulses (a B(n), 6 or 7 at 1 mm), and the passes end more than 2 pulses apart;
// the same cut with the atomic ISRs ends within 2 pulses. (The chance of a hit per spindle pulse is the motor
// pulse rate times the few-us windows, so it grows with the spindle speed.)
TEST(LatheThread, SeedNestedPulseIsrsShiftTheHelix) {
    EXPECT_GT(m6_metrics(three_passes(200.0, LATHE_SYNC_ELF)).phase_error_end_um, 2 * kPulseUm);
    EXPECT_LT(m6_metrics(three_passes(200.0, LATHE_SYNC_ATOMIC_ELF)).phase_error_end_um, 2 * kPulseUm);
}

TEST(LatheThread, SpindleTooFastSaturatesAndTheErrorGrows) {
    // 700 rpm at 1 mm asks 11.7 mm/s of carriage, 1.34 x the motor's 8.70 mm/s at 100 % duty (about 522 rpm, from
    // §4.3).
    LatheBench b(700.0);
    thread_m6(b, 1, 4.0);
    ASSERT_FALSE(b.passes.empty());
    const auto& motor = b.passes.front().motor_pulses;
    ASSERT_GT(motor.size(), 200U);
    // Following error in motor pulses: lambda = 6.1417 per spindle pulse asked, against the pulses counted.
    const auto lag = [&](std::size_t k) {
        return 780.0 / 127.0 * static_cast<double>(k) - static_cast<double>(motor[k] - motor[0]);
    };
    const std::size_t mid = motor.size() / 2;
    const std::size_t end = motor.size() - 1;
    // Full speed is 2136.75 pulses/s against 700 / 60 x 40 x 6.1417 = 2866 asked: the lag grows by about 730
    // pulses a second, so over the second half it must grow by at least half that rate.
    const double seconds = static_cast<double>(end - mid) / (700.0 / 60.0 * 40.0);
    EXPECT_GT(lag(end) - lag(mid), 0.5 * 730.0 * seconds);
    EXPECT_GT(lag(end), lag(mid));
}

}  // namespace
