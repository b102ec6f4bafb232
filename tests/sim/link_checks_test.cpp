// The link checks shared by the UART architectures (sim/systems/link_checks.hpp).
#include <gtest/gtest.h>

#include "architectures/serial_host/link_checks.hpp"
#include "support/bad_input_message.hpp"

using namespace cnc::sim;
using cnc::test::bad_input_message;

// AN205: the CP2102 divides 24 MHz by round(24 MHz / rate): 57600 -> 417 -> 57 553.96 Bd.
TEST(LinkChecks, TheHostEndIsTheCp2102sActualRate) {
    cnc::uart::Cp2102Config link;
    link.requested_baud = 57'600;
    const LineEnd real = cp2102_end(link);
    EXPECT_DOUBLE_EQ(real.baud, 24e6 / 417);
    EXPECT_EQ(real.setting, "link.baud = 57600 (the CP2102 runs 57553.96 Bd)");
    link.ideal_baud = true;
    const LineEnd ideal = cp2102_end(link);
    EXPECT_DOUBLE_EQ(ideal.baud, 57'600.0);
    EXPECT_EQ(ideal.setting, "link.baud = 57600 (link.ideal_baud: exactly 57600 Bd)");
}

// 2 % apart passes (8N1 allows 2.63 %); 3 % apart is refused, naming both ends and the bound's derivation.
TEST(LinkChecks, RatesBeyondTheToleranceAreRefusedNamingBothEnds) {
    EXPECT_NO_THROW(check_line_rates("s.toml: a, b", {100'000.0, "host"}, {102'000.0, "receiver"}));
    const std::string err = bad_input_message([] {
        check_line_rates("s.toml: a, b", {103'000.0, "the host"}, {100'000.0, "the MCU"});
    });
    EXPECT_EQ(err,
              "s.toml: a, b: baud mismatch: the host against the MCU: the host's line runs +3.00 % off the "
              "receiver's rate, and 8N1 works within +-2.63 % (the stop bit is sampled 9.5 bits after the start "
              "edge: 0.5 / 9.5 = 5.26 % at most, halved for margin); give both ends one rate");
}

// None tolerated: the line has no noise, so one framing error is one byte of the job lost or changed.
TEST(LinkChecks, TheFirstFramingErrorAtEitherEndStopsTheRun) {
    EXPECT_FALSE(framing_failure(0, "FPGA", 0).has_value());
    const auto at_fpga = framing_failure(1, "FPGA", 0);
    ASSERT_TRUE(at_fpga.has_value());
    EXPECT_EQ(*at_fpga,
              "the link garbles frames: 1 framing errors at the FPGA, 0 at the CP2102 (a byte of the job "
              "was lost or changed, so the run is stopped)");
    EXPECT_TRUE(framing_failure(0, "MCU", 2).has_value());
}
