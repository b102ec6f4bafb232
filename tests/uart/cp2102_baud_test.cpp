#include <gtest/gtest.h>

#include "common/bad_input.hpp"
#include "uart/core/cp2102_baud.hpp"
#include "uart/core/usb_timing.hpp"

using namespace cnc::uart;

TEST(Cp2102Baud, SeedRate115200Is208ClocksOf24MHz) {
    const Cp2102Baud b = cp2102_baud(115'200);
    EXPECT_EQ(b.table_rate, 115'200U);
    EXPECT_EQ(b.divider, 208);
    EXPECT_NEAR(b.actual_bd, 115'384.615, 0.001);
    EXPECT_NEAR(b.error_pct, 0.160, 0.001);
    EXPECT_EQ(b.bit_clock().bit_edge(1), 8'666'666);
}

TEST(Cp2102Baud, Rate57600Is417Clocks) {
    const Cp2102Baud b = cp2102_baud(57'600);
    EXPECT_EQ(b.divider, 417);
    EXPECT_NEAR(b.actual_bd, 57'553.957, 0.001);
    EXPECT_NEAR(b.error_pct, -0.0799, 0.0001);
}

TEST(Cp2102Baud, An205RangeEdges) {
    EXPECT_EQ(cp2102_table_rate(77'608), 76'800U);
    EXPECT_EQ(cp2102_table_rate(77'609), 115'200U);
    EXPECT_EQ(cp2102_table_rate(117'028), 115'200U);
    EXPECT_EQ(cp2102_table_rate(117'029), 128'000U);
    EXPECT_EQ(cp2102_table_rate(129'347), 128'000U);
    EXPECT_EQ(cp2102_table_rate(129'348), 153'600U);
    EXPECT_EQ(cp2102_table_rate(58'053), 57'600U);
    EXPECT_EQ(cp2102_table_rate(58'054), 64'000U);
    EXPECT_EQ(cp2102_table_rate(57), 300U);
    EXPECT_EQ(cp2102_table_rate(1'053'257), 921'600U);
    EXPECT_EQ(cp2102_table_rate(9'612), 9'600U);
    EXPECT_EQ(cp2102_table_rate(9'613), 14'400U);
    // A request that aliases to another rate is off by the aliasing, not only by the divider.
    const Cp2102Baud b = cp2102_baud(110'000);
    EXPECT_EQ(b.table_rate, 115'200U);
    EXPECT_NEAR(b.error_pct, 4.895, 0.001);
    EXPECT_EQ(cp2102_baud(300).divider, 80'000);  // prescale 4 x 20 000
    EXPECT_DOUBLE_EQ(cp2102_baud(300).actual_bd, 300.0);
}

TEST(Cp2102Baud, UnsupportedRatesAreBadInput) {
    EXPECT_THROW((void)cp2102_baud(0), cnc::BadInput);
    EXPECT_THROW((void)cp2102_baud(56), cnc::BadInput);
    EXPECT_THROW((void)cp2102_baud(1'053'258), cnc::BadInput);
    EXPECT_THROW((void)cp2102_baud(2'000'000), cnc::BadInput);
    EXPECT_THROW((void)cp2102_baud(0, true), cnc::BadInput);
}

TEST(Cp2102Baud, IdealRateIsExact) {
    const Cp2102Baud b = cp2102_baud(115'200, true);
    EXPECT_DOUBLE_EQ(b.actual_bd, 115'200.0);
    EXPECT_DOUBLE_EQ(b.error_pct, 0.0);
    EXPECT_EQ(b.bit_clock().bit_edge(1), 8'680'555);    // 1e12 / 115200 rounded down
    EXPECT_EQ(b.bit_clock().bit_edge(10), 86'805'555);  // from the tick count, not 10 x the rounded bit
}

TEST(UsbTiming, NextFrameStart) {
    EXPECT_EQ(next_frame_start(300'000'000'000), 300'000'000'000);  // on a frame start: that frame
    EXPECT_EQ(next_frame_start(300'000'000'001), 301'000'000'000);
    EXPECT_EQ(next_frame_start(2, 1'000, 3), 3);
    EXPECT_EQ(next_frame_start(5, 1'000, 3), 1'003);
    EXPECT_EQ(next_frame_start(-1'500, 1'000, 0), -1'000);
    EXPECT_THROW((void)next_frame_start(0, 0), cnc::BadInput);
}
