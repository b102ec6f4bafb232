// Gearbox, belt, leadscrew and backlash (seed 002 §2.3, §4.2): 780 motor-encoder pulses per leadscrew revolution.
#include <gtest/gtest.h>

#include "lathe/core/drive_train.hpp"

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

// 30 slots x 26 = 780 pulses per 3.175 mm: 4.0705 um per pulse (LS_PPR and LS_PITCH of §2.5.3).
TEST(DriveTrain, OneMotorPulseIs4Point07Um) {
    cnc::lathe::DriveTrain d({});
    EXPECT_NEAR(d.follow(kTwoPi / 30.0) * 1000.0, 3.175 / 780.0 * 1000.0, 1e-9);
    EXPECT_NEAR(3.175 / 780.0 * 1000.0, 4.0705, 1e-4);
}

// A reduction belt (belt_ratio gearbox-output turns per leadscrew turn) divides the travel as the gearbox does:
// with 2:1, one motor pulse is half of 3.175 mm / 780.
TEST(DriveTrain, BeltReductionDividesTheTravel) {
    cnc::lathe::DriveTrainParams p;
    p.belt_ratio = 2.0;
    cnc::lathe::DriveTrain d(p);
    EXPECT_NEAR(d.follow(kTwoPi / 30.0), 3.175 / 780.0 / 2.0, 1e-12);
}

// With 0.1 mm of play: a reversal moves the gearbox through the play before the carriage follows (§4.2.1).
TEST(DriveTrain, BacklashHoldsTheCarriageOnReversal) {
    cnc::lathe::DriveTrainParams p;
    p.backlash_mm = 0.1;
    cnc::lathe::DriveTrain d(p);
    const double per_mm = kTwoPi * 26.0 / 3.175;       // motor radians per mm
    EXPECT_NEAR(d.follow(1.0 * per_mm), 0.95, 1e-12);  // pushed from the far side of the play
    EXPECT_NEAR(d.follow(0.9 * per_mm), 0.95, 1e-12);  // reversed by less than the play: no motion
    EXPECT_NEAR(d.follow(0.8 * per_mm), 0.85, 1e-12);  // the play taken up the other way
}

}  // namespace
