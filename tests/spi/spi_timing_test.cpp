// Mode 0 transfer timing: SCLK edge offsets and transfer time = cs_setup + bits/SCLK + cs_hold, exact in ps.
#include <gtest/gtest.h>

#include <string>

#include "common/bad_input.hpp"
#include "spi/core/spi_timing.hpp"

namespace cnc::spi {
namespace {

TEST(SpiTiming, TransferTimeIsSetupPlusBitsPlusHold) {
    const SpiConfig cfg;                                                         // 5 MHz, 1 us setup, 1 us hold
    EXPECT_EQ(transfer_time_ps(cfg, 72), 1'000'000 + 72 * 200'000 + 1'000'000);  // 16.4 us
    EXPECT_EQ(transfer_slot_ps(cfg, 72), 17'400'000);
    SpiConfig c3 = cfg;
    c3.sclk_hz = 3'000'000;  // 333 333.33 ps per bit: the total is rounded once, not per bit
    c3.cs_setup_ps = 123;
    c3.cs_hold_ps = 0;
    EXPECT_EQ(transfer_time_ps(c3, 72), 123 + 24'000'000);
    EXPECT_EQ(transfer_time_ps(c3, 10), 123 + 3'333'333);
}

TEST(SpiTiming, SclkEdgesAreHalfPeriodsAfterSetup) {
    SpiConfig cfg;
    EXPECT_EQ(sclk_rise_ps(cfg, 0), 1'000'000);
    EXPECT_EQ(sclk_fall_ps(cfg, 0), 1'100'000);
    EXPECT_EQ(sclk_rise_ps(cfg, 71), 1'000'000 + 71 * 200'000);
    EXPECT_EQ(sclk_fall_ps(cfg, 71), 1'000'000 + 71 * 200'000 + 100'000);
    EXPECT_EQ(sclk_half_period_ps(cfg), 100'000);
    cfg.sclk_hz = 3'000'000;
    EXPECT_EQ(sclk_fall_ps(cfg, 0), 1'000'000 + 166'666);
    EXPECT_EQ(sclk_rise_ps(cfg, 3), 1'000'000 + 1'000'000);  // exact after 3 periods: no drift
}

TEST(SpiTiming, FrameThatDoesNotFitTheServoPeriodIsRefused) {
    SpiConfig cfg;
    EXPECT_NO_THROW(check_transfer_fits(cfg, 72, kPsPerMs));
    EXPECT_NO_THROW(check_transfer_fits(cfg, 72, 17'400'000));  // exactly one slot
    cfg.sclk_hz = 100'000;                                      // 72 bits take 720 us, + 2 us + 1 us idle
    EXPECT_NO_THROW(check_transfer_fits(cfg, 72, kPsPerMs));
    cfg.sclk_hz = 50'000;  // 1440 us
    try {
        check_transfer_fits(cfg, 72, kPsPerMs);
        FAIL() << "no BadInput";
    } catch (const BadInput& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind("spi: sclk_hz: ", 0), 0U) << msg;
        EXPECT_NE(msg.find("72-bit frame at 50000 Hz takes 1442 us"), std::string::npos) << msg;
        EXPECT_NE(msg.find("1443 us with the SS-high gap"), std::string::npos) << msg;
        EXPECT_NE(msg.find("1000 us servo period"), std::string::npos) << msg;
    }
}

TEST(SpiTiming, ValidateNamesTheKey) {
    SpiConfig cfg;
    EXPECT_NO_THROW(validate(cfg));
    cfg.sclk_hz = 0;
    EXPECT_THROW(validate(cfg), BadInput);
    cfg = SpiConfig{};
    cfg.cs_setup_ps = 0;
    try {
        validate(cfg);
        FAIL() << "no BadInput";
    } catch (const BadInput& e) {
        EXPECT_EQ(std::string(e.what()).rfind("spi: cs_setup_ps: ", 0), 0U) << e.what();
    }
    cfg = SpiConfig{};
    cfg.cs_hold_ps = -1;
    EXPECT_THROW(validate(cfg), BadInput);
    cfg = SpiConfig{};
    cfg.ss_idle_min_ps = 0;
    EXPECT_THROW(validate(cfg), BadInput);
}

}  // namespace
}  // namespace cnc::spi
