// Issue 12 check 4: the seed 002 firmware (our C, on the ATmega16 model) cutting an M6 thread (1.0 mm) as a
// machinist would key it in (§6.6): 1 (cut), 3 (thread), pitch 1#00 D, 1 (hand), length 10 D, then D to cut and
// D to retract, with the spindle faster than the motor can follow.
#include <gtest/gtest.h>

#include <vector>

#include "lathe_bench.hpp"

namespace {

using namespace cnc::lathe::test;

struct Sample {
    double rev;     // spindle revolutions since power-up
    double x_mm;    // carriage
    long motor;     // motor pulses (falling edges at the MCU) since power-up
};

// Records the carriage at each spindle pulse while the bridge drives the cut direction (EN pulsing within the
// last 0.5 ms, DIR as at the first cut); a gap of more than 0.3 s starts a new pass.
struct ThreadBench : LatheBench {
    using LatheBench::LatheBench;

    void on_spindle_pulse() override {
        const bool dir1 = chip.pin_level(Pin{'D', 0});
        const bool dir2 = chip.pin_level(Pin{'D', 1});
        const double now_s = static_cast<double>(chip.cycle()) * kCycleS;
        if (dir1 == dir2 || now_s - last_drive_s > 5e-4) return;
        if (!cut_dir1) cut_dir1 = dir1;
        if (dir1 != *cut_dir1) return;
        if (passes.empty() || now_s - last_sample_s > 0.3) passes.emplace_back();
        passes.back().push_back({spindle_rev(), train.carriage_mm(), motor_pulses});
        last_sample_s = now_s;
    }

    void cut_step() {
        const bool before = motor_level;
        step();
        if (before && !motor_level) ++motor_pulses;
        if (chip.pin_level(Pin{'D', 5})) last_drive_s = static_cast<double>(chip.cycle()) * kCycleS;
    }

    void run_cut_for(double s) {
        const Cycle end = chip.cycle() + static_cast<Cycle>(s * 8e6);
        while (chip.cycle() < end) cut_step();
    }

    void key(char k) {
        pressed = {key_pos(k)};
        run_cut_for(0.1);
        pressed.clear();
        run_cut_for(0.4);
    }

    void thread_m6(int passes_wanted) {
        run_cut_for(0.3);
        for (const char k : std::string("131#00D110D")) key(k);
        for (int p = 0; p < passes_wanted; ++p) {
            key('D');           // press OK to cut
            run_cut_for(4.0);   // 10 revolutions, brake, slip shown 1 s
            key('D');           // OK to retract
            run_cut_for(3.0);
        }
    }

    std::vector<std::vector<Sample>> passes;
    std::optional<bool> cut_dir1;
    double last_drive_s = -1.0;
    double last_sample_s = -1.0;
    long motor_pulses = 0;
};

TEST(LatheThread, SpindleTooFastSaturatesAndTheErrorGrows) {
    // 700 rpm at 1 mm asks 11.7 mm/s of carriage, 1.34 x the motor's 8.70 mm/s at 100 % duty (§10: about 522 rpm).
    ThreadBench b(700.0);
    b.thread_m6(1);
    ASSERT_FALSE(b.passes.empty());
    const auto& p = b.passes.front();
    ASSERT_GT(p.size(), 200U);
    // Following error in motor pulses: lambda = 6.1417 per spindle pulse asked, against the pulses counted.
    const auto lag = [&](std::size_t k) {
        return 780.0 / 127.0 * static_cast<double>(k) - static_cast<double>(p[k].motor - p[0].motor);
    };
    const std::size_t mid = p.size() / 2;
    const std::size_t end = p.size() - 1;
    // Full speed is 2136.75 pulses/s against 700 / 60 x 40 x 6.1417 = 2866 asked: the lag grows by about 730
    // pulses a second, so over the second half it must grow by at least half that rate.
    const double seconds = static_cast<double>(end - mid) / (700.0 / 60.0 * 40.0);
    EXPECT_GT(lag(end) - lag(mid), 0.5 * 730.0 * seconds);
    EXPECT_GT(lag(end), lag(mid));
}

}  // namespace
