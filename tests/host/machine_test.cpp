#include <gtest/gtest.h>

#include "host/core/machine.hpp"
#include "host_test_util.hpp"

namespace cnc::host {
namespace {

using test::expect_bad_input;

TEST(HostMachine, DefaultIsTheSeedReferenceMachine) {
    const AxisMachine axis;
    EXPECT_DOUBLE_EQ(axis.steps_per_rev(), 6400.0);  // seed 000 T3.4
    EXPECT_DOUBLE_EQ(axis.travel_per_rev_mm(), 40.0);
    EXPECT_DOUBLE_EQ(axis.steps_per_mm(), 160.0);
    EXPECT_DOUBLE_EQ(axis.mm_per_step(), 0.00625);
}

TEST(HostMachine, LeadscrewUsesLeadTimesStartsAndGearRatio) {
    AxisMachine axis;
    axis.transmission = Transmission::Leadscrew;
    axis.microsteps = 16;
    EXPECT_DOUBLE_EQ(axis.steps_per_mm(), 400.0);  // 3200 steps/rev over an 8 mm lead
    axis.screw_starts = 4;
    EXPECT_DOUBLE_EQ(axis.steps_per_mm(), 100.0);
    axis.gear_ratio = 3.0;
    EXPECT_DOUBLE_EQ(axis.steps_per_mm(), 300.0);
}

TEST(HostMachine, BeltWithOtherPulleyAndMicrosteps) {
    AxisMachine axis;
    axis.microsteps = 16;
    axis.pulley_teeth = 16;
    EXPECT_DOUBLE_EQ(axis.steps_per_mm(), 100.0);  // 3200 / 32 mm
    axis.step_angle_deg = 0.9;
    EXPECT_DOUBLE_EQ(axis.steps_per_mm(), 200.0);
}

TEST(HostMachine, CalibratedStepsPerMmReplacesTheTransmission) {
    AxisMachine axis;
    axis.microsteps = 16;
    axis.calibrated_steps_per_mm = 100.0;
    EXPECT_DOUBLE_EQ(axis.steps_per_mm(), 100.0);
    EXPECT_DOUBLE_EQ(axis.transmission_steps_per_mm(), 80.0);  // 3200 steps/rev over the GT2 20T's 40 mm
    EXPECT_DOUBLE_EQ(axis.mm_per_step(), 0.01);
    // 100 microsteps/mm at 1/16 are 6.25 full steps/mm: 200 full steps per revolution move the carriage 32 mm.
    EXPECT_DOUBLE_EQ(axis.travel_per_motor_rev_mm(), 32.0);
}

TEST(HostMachine, TravelPerMotorRevolutionFollowsTheTransmission) {
    AxisMachine axis;
    axis.gear_ratio = 4.0;
    EXPECT_DOUBLE_EQ(axis.travel_per_motor_rev_mm(), 10.0);  // 40 mm per pulley revolution, 4 motor revolutions
}

TEST(HostMachine, ValidateAcceptsEveryDrv8825Mode) {
    for (int m : {1, 2, 4, 8, 16, 32}) {
        AxisMachine axis;
        axis.microsteps = m;
        EXPECT_NO_THROW(validate(axis, "m.toml: machine.x"));
    }
}

TEST(HostMachine, ValidateRejectsImpossibleValues) {
    const auto rejects = [](auto change, std::initializer_list<std::string> parts) {
        AxisMachine axis;
        change(axis);
        expect_bad_input([&] { validate(axis, "m.toml: machine.x"); }, parts);
    };
    rejects([](AxisMachine& a) { a.microsteps = 3; }, {"m.toml: machine.x: ", "microsteps 3", "1, 2, 4, 8, 16, 32"});
    rejects([](AxisMachine& a) { a.microsteps = 64; }, {"microsteps 64"});
    rejects([](AxisMachine& a) { a.step_angle_deg = 0.0; }, {"step_angle_deg 0", "> 0"});
    rejects([](AxisMachine& a) { a.step_angle_deg = 400.0; }, {"step_angle_deg 400", "<= 360"});
    rejects([](AxisMachine& a) { a.pulley_teeth = 0; }, {"pulley_teeth 0", "> 0"});
    rejects([](AxisMachine& a) { a.belt_pitch_mm = -2.0; }, {"belt_pitch_mm -2"});
    rejects([](AxisMachine& a) { a.gear_ratio = 0.0; }, {"gear_ratio 0"});
    rejects([](AxisMachine& a) { a.travel_mm = -1.0; }, {"travel_mm -1"});
    rejects([](AxisMachine& a) { a.calibrated_steps_per_mm = 0.0; }, {"steps_per_mm 0", "> 0"});
    rejects(
        [](AxisMachine& a) {
            a.transmission = Transmission::Leadscrew;
            a.lead_mm = 0.0;
        },
        {"lead_mm 0"});
    rejects(
        [](AxisMachine& a) {
            a.transmission = Transmission::Leadscrew;
            a.screw_starts = 0;
        },
        {"screw_starts 0"});
}

TEST(HostMachine, LeadscrewIgnoresBeltFields) {
    AxisMachine axis;
    axis.transmission = Transmission::Leadscrew;
    axis.pulley_teeth = 0;  // not used by a leadscrew axis
    EXPECT_NO_THROW(validate(axis, "m"));
}

TEST(HostMachine, ValidateMachineNamesTheAxis) {
    MachineModel m;
    m.y.microsteps = 5;
    expect_bad_input([&] { validate(m, "machine"); }, {"machine y: microsteps 5"});
}

}  // namespace
}  // namespace cnc::host
