// The rate tolerance of an asynchronous line (models/uart/core/rate_tolerance.hpp) against the frame arithmetic
// and the links of the seeds.
#include <gtest/gtest.h>

#include "uart/core/rate_tolerance.hpp"

using namespace cnc::uart;

// 8N1: start + 8 data bits, then the middle of the stop bit: 9.5 bit times; with even parity one more.
TEST(RateTolerance, StopBitSampleAndAllowedMismatch) {
    EXPECT_DOUBLE_EQ(stop_sample_bits(kFormat8N1), 9.5);
    EXPECT_DOUBLE_EQ(stop_sample_bits(FrameFormat{8, Parity::Even, 1}), 10.5);
    EXPECT_DOUBLE_EQ(stop_sample_bits(FrameFormat{7, Parity::None, 2}), 8.5);  // the second stop bit adds nothing
    // half of 0.5 bit / 9.5 bits = 1/38 = 2.63 %
    EXPECT_DOUBLE_EQ(max_rate_mismatch(kFormat8N1), 1.0 / 38.0);
    EXPECT_NEAR(max_rate_mismatch(kFormat8N1) * 100.0, 2.63, 0.005);
}

// The links of the seeds, from their data sheets and listings: each end's rate is its clock over its divider.
TEST(RateTolerance, SeedLinksPassAndMismatchedOnesDoNot) {
    const double cp2102_57600 = 24e6 / 417;  // AN205: 24 MHz / round(24 MHz / 57600)
    const double cp2102_115200 = 24e6 / 208;
    const double cp2102_51200 = 24e6 / 469;         // scenarios/atmega/baud_mismatch.toml
    const double avr_ubrr16 = 16e6 / (16 * 17);     // seed 003 §5.3.1: UBRR0 = 16, U2X0 = 0
    const double avr_ubrr16_u2x = 16e6 / (8 * 17);  // grbl 1.1 at 115200: UBRR0 = 16, U2X0 = 1
    const double fpga_115200 = 50e6 / 434;          // seed 000 §5.2.1 FULL_BIT = 434

    EXPECT_NEAR(rate_mismatch(avr_ubrr16, cp2102_57600) * 100.0, 2.206, 0.001);
    EXPECT_TRUE(rates_within_tolerance(cp2102_57600, avr_ubrr16, kFormat8N1));
    EXPECT_TRUE(rates_within_tolerance(cp2102_115200, fpga_115200, kFormat8N1));
    EXPECT_TRUE(rates_within_tolerance(cp2102_115200, avr_ubrr16_u2x, kFormat8N1));  // -1.92 %

    EXPECT_NEAR(rate_mismatch(cp2102_51200, avr_ubrr16) * 100.0, -13.006, 0.001);  // 272 / 469 x 1.5 - 1
    EXPECT_FALSE(rates_within_tolerance(cp2102_51200, avr_ubrr16, kFormat8N1));
    EXPECT_FALSE(rates_within_tolerance(cp2102_57600, fpga_115200, kFormat8N1));
    EXPECT_FALSE(rates_within_tolerance(cp2102_57600, avr_ubrr16_u2x, kFormat8N1));  // grbl at the seed's rate
}

// Both directions count: a 0.1 % of the limit inside it on either side passes, as far beyond it fails; and a
// sender 1/38 slow is a receiver 1/37 fast from the other end: beyond.
TEST(RateTolerance, BothDirectionsAreChecked) {
    const double b = 100'000.0;
    const double limit = 1.0 / 38.0;
    EXPECT_TRUE(rates_within_tolerance(b * (1.0 + 0.999 * limit), b, kFormat8N1));
    EXPECT_TRUE(rates_within_tolerance(b, b * (1.0 + 0.999 * limit), kFormat8N1));
    EXPECT_FALSE(rates_within_tolerance(b * (1.0 + 1.001 * limit), b, kFormat8N1));
    EXPECT_FALSE(rates_within_tolerance(b, b * (1.0 + 1.001 * limit), kFormat8N1));
    EXPECT_FALSE(rates_within_tolerance(b * (1.0 - limit), b, kFormat8N1));
}
