#include <gtest/gtest.h>

#include "common/bad_input.hpp"
#include "mechanics/core/ideal_stepper.hpp"
#include "mechanics/core/transmission.hpp"

using namespace cnc::mech;

TEST(IdealStepperBelt, OneRevolutionIs40mmAt160StepsPerMm) {
    // seed 000 §3.4.2 (T3.4): 1.8 deg, 1/32, GT2 (2 mm) x 20 teeth -> 6400 microsteps per 40 mm = 160 steps/mm
    IdealStepper motor(1.8);
    const Belt belt(20, 2.0);
    motor.on_microstep(0, 6'400, 32);
    EXPECT_DOUBLE_EQ(motor.shaft_angle_deg(0), 360.0);
    EXPECT_DOUBLE_EQ(belt.carriage_mm(motor.shaft_angle_deg(0)), 40.0);
    motor.on_microstep(1, -160, 32);
    EXPECT_DOUBLE_EQ(belt.carriage_mm(motor.shaft_angle_deg(1)), -1.0);
    motor.on_microstep(2, 3, 1);  // full-step units
    EXPECT_DOUBLE_EQ(motor.shaft_angle_deg(2), 5.4);
}

TEST(Transmission, LeadscrewAndGearRatio) {
    EXPECT_DOUBLE_EQ(Leadscrew(8.0).carriage_mm(360.0), 8.0);
    EXPECT_DOUBLE_EQ(Leadscrew(2.0, 4).carriage_mm(360.0), 8.0);  // Tr8x8: 2 mm pitch, 4 starts
    EXPECT_DOUBLE_EQ(Leadscrew(8.0, 1, 2.0).carriage_mm(360.0), 4.0);
    EXPECT_DOUBLE_EQ(Belt(20, 2.0, 4.0).travel_per_motor_rev_mm(), 10.0);
    EXPECT_DOUBLE_EQ(Belt(28, 2.0).carriage_mm(1.8), 0.28);  // seed 000 Fig. 2.7 printed column (28-tooth pulley)
}

TEST(Transmission, CalibratedDriveMovesItsTravelPerRevolution) {
    EXPECT_DOUBLE_EQ(CalibratedDrive(32.0).carriage_mm(360.0), 32.0);
    EXPECT_DOUBLE_EQ(CalibratedDrive(32.0).carriage_mm(-90.0), -8.0);
}

TEST(Transmission, NonPositiveParametersAreBadInput) {
    EXPECT_THROW(CalibratedDrive(0.0), cnc::BadInput);
    EXPECT_THROW(Belt(0, 2.0), cnc::BadInput);
    EXPECT_THROW(Belt(20, -2.0), cnc::BadInput);
    EXPECT_THROW(Belt(20, 2.0, 0.0), cnc::BadInput);
    EXPECT_THROW(Leadscrew(0.0), cnc::BadInput);
    EXPECT_THROW(Leadscrew(2.0, 0), cnc::BadInput);
    EXPECT_THROW(IdealStepper(0.0), cnc::BadInput);
}
