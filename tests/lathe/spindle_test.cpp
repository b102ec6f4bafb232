// The spindle's droop under a cutting torque against the analytic first-order response, and the cutting torque
// against a hand calculation.
#include <gtest/gtest.h>

#include <cmath>

#include "lathe/core/spindle.hpp"

namespace {

using cnc::lathe::CutParams;
using cnc::lathe::cutting_torque_nm;
using cnc::lathe::Spindle;
using cnc::lathe::SpindleParams;

// 2000 N/mm^2 x 0.1 mm deep x 1.0 mm per revolution = 200 N at a 6 mm workpiece's 3 mm radius = 0.6 N m.
TEST(Spindle, CuttingTorque) {
    EXPECT_NEAR(cutting_torque_nm(CutParams{0.1, 2000.0, 6.0}, 1.0), 0.6, 1e-12);
    EXPECT_EQ(cutting_torque_nm(CutParams{0.0, 2000.0, 6.0}, 1.0), 0.0);
}

// 60 rpm, 2 %/N m, tau = 20 ms, 1.5 N m from t = 0: the deficit settles at 1 rev/s x 2 % x 1.5 = 0.03 rev/s
// (1.8 rpm); speed 1 - 0.03 (1 - e^(-t/tau)) rev/s, position t - 0.03 (t - tau (1 - e^(-t/tau))) rev. Stepped
// 1 us as the rig does.
TEST(Spindle, FirstOrderDroopMatchesAnalytic) {
    const double tau = 0.02, d_inf = 0.03;
    Spindle s(SpindleParams{60.0, 2.0, tau});
    for (int i = 1; i <= 100000; ++i) {
        const double t = i * 1e-6;
        s.advance_to(t, 1.5);
        if (i % 10000 == 0) {
            const double decay = std::exp(-t / tau);
            EXPECT_NEAR(s.rpm(), (1.0 - d_inf * (1.0 - decay)) * 60.0, 1e-9) << t;
            EXPECT_NEAR(s.rev(), t - d_inf * (t - tau * (1.0 - decay)), 1e-9) << t;
        }
    }
    // The load off at 0.1 s: the deficit decays from its value then with the same time constant.
    const double d0 = d_inf * (1.0 - std::exp(-0.1 / tau));
    s.advance_to(0.15, 0.0);
    EXPECT_NEAR(s.rpm(), (1.0 - d0 * std::exp(-0.05 / tau)) * 60.0, 1e-9);
}

// No load: the spindle turns at its set speed exactly (the rig's unloaded runs depend on it).
TEST(Spindle, NoLoadIsExact) {
    Spindle s(SpindleParams{60.0, 2.0, 0.02});
    for (int i = 1; i <= 1000; ++i) s.advance_to(i * 1e-3, 0.0);
    EXPECT_EQ(s.rev(), 1.0);
    EXPECT_EQ(s.rpm(), 60.0);
}

// A time constant of 0: the droop follows the torque at once.
TEST(Spindle, NoLagDroopsAtOnce) {
    Spindle s(SpindleParams{120.0, 1.0, 0.0});
    s.advance_to(0.5, 2.0);
    EXPECT_NEAR(s.rpm(), 120.0 * (1.0 - 0.02), 1e-12);
    EXPECT_NEAR(s.rev(), 2.0 * 0.98 * 0.5, 1e-12);
}

}  // namespace
