// The laser PWM's law (fpga/core/laser_pwm.hpp) against hand-worked periods and duties.
#include <gtest/gtest.h>

#include "fpga/core/laser_pwm.hpp"

namespace cnc::fpga {
namespace {

TEST(LaserPwm, PeriodIsAWholeNumberOfClocksOrNone) {
    EXPECT_EQ(laser_pwm_period_cycles(50'000'000, 7812.5), 6400U);  // grbl's 16 MHz / 2048
    EXPECT_EQ(laser_pwm_period_cycles(50'000'000, 12'500.0), 4000U);
    EXPECT_EQ(laser_pwm_period_cycles(50'000'000, 1000.0), 50'000U);
    EXPECT_FALSE(laser_pwm_period_cycles(50'000'000, 3000.0));  // 16,666.67 clocks
    EXPECT_FALSE(laser_pwm_period_cycles(50'000'000, 0.0));
}

TEST(LaserPwm, HighTimeIsSOverSMaxOfThePeriodRoundedAndHeld) {
    EXPECT_EQ(laser_high_cycles(500.0, 1000.0, 6400), 3200);
    EXPECT_EQ(laser_high_cycles(100.0, 1000.0, 6400), 640);
    EXPECT_EQ(laser_high_cycles(1.0, 3.0, 100), 33);           // 33.33 rounds down
    EXPECT_EQ(laser_high_cycles(2.0, 3.0, 100), 67);           // 66.67 rounds up
    EXPECT_EQ(laser_high_cycles(1500.0, 1000.0, 6400), 6400);  // held to full power
    EXPECT_EQ(laser_high_cycles(-5.0, 1000.0, 6400), 0);
}

TEST(LaserPwm, PinIsHighForTheFirstHighClocksOfEachPeriod) {
    EXPECT_TRUE(laser_pwm_high(0, 3, 10));
    EXPECT_TRUE(laser_pwm_high(2, 3, 10));
    EXPECT_FALSE(laser_pwm_high(3, 3, 10));
    EXPECT_FALSE(laser_pwm_high(9, 3, 10));
    EXPECT_TRUE(laser_pwm_high(10, 3, 10));
    EXPECT_FALSE(laser_pwm_high(0, 0, 10));
    EXPECT_TRUE(laser_pwm_high(9, 10, 10));
}

TEST(LaserPwm, NextChangeAtTheHighTimeThenAtTheWrap) {
    EXPECT_EQ(laser_pwm_next_change(0, 3, 10), 3);
    EXPECT_EQ(laser_pwm_next_change(2, 3, 10), 1);
    EXPECT_EQ(laser_pwm_next_change(3, 3, 10), 7);
    EXPECT_EQ(laser_pwm_next_change(19, 3, 10), 1);
    EXPECT_FALSE(laser_pwm_next_change(5, 0, 10));   // held low
    EXPECT_FALSE(laser_pwm_next_change(5, 10, 10));  // held high
}

}  // namespace
}  // namespace cnc::fpga
