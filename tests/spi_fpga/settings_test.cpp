// The spi-fpga scenario keys (sim/architectures/spi_fpga/spi_fpga_settings.cpp): defaults, units, and the refusals that name
// the key (at the loader level; the CLI's exit code 2 is checked by the bad_input ctests).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "architectures/spi_fpga/spi_fpga_settings.hpp"
#include "common/bad_input.hpp"
#include "scenario/scenario.hpp"
#include "support/test_path.hpp"

using cnc::kPsPerNs;
using cnc::kPsPerUs;

namespace {

std::string write_scenario(const std::string& name, const std::string& text) {
    const std::string path = cnc::test::test_path(name + ".toml");
    std::ofstream(path) << text;
    return path;
}

const char* kJob = "[scenario]\narchitecture = \"spi-fpga\"\njob = \"square.nc\"\n";

std::string load_error(const std::string& text, const std::vector<std::string>& sets = {}) {
    try {
        cnc::sim::load_scenario(write_scenario("error", text), sets);
    } catch (const cnc::BadInput& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(SpiFpgaSettings, Defaults) {
    const auto s = cnc::sim::load_scenario(write_scenario("defaults", kJob), {});
    const auto& c = s.settings<cnc::sim::SpiFpgaSettings>();
    EXPECT_EQ(c.servo.period_ps, 1'000 * kPsPerUs);
    EXPECT_EQ(c.servo.latency.max_ps, 50 * kPsPerUs);
    EXPECT_EQ(c.servo.latency.distribution, cnc::host::servo::LatencyDistribution::Exponential);
    EXPECT_DOUBLE_EQ(c.servo.position_gain, 0.5);
    EXPECT_DOUBLE_EQ(c.servo.deadband_steps, 1.0);
    EXPECT_DOUBLE_EQ(c.servo.stepgen_margin, 0.25);
    EXPECT_EQ(c.servo.clk_hz, 50'000'000U);
    EXPECT_EQ(c.servo.min_period_cycles, 101U);
    EXPECT_EQ(c.link.sclk_hz, 5'000'000U);
    EXPECT_EQ(c.link.cs_setup_ps, 1'000 * kPsPerNs);
    EXPECT_EQ(c.link.cs_hold_ps, 1'000 * kPsPerNs);
    EXPECT_EQ(c.link.ss_idle_min_ps, 1'000 * kPsPerNs);
    EXPECT_FALSE(c.link.trace_wires);
    EXPECT_EQ(c.fpga.fifo_depth, 4U);
    EXPECT_EQ(c.fpga.pulse_cycles, 100U);
    EXPECT_EQ(c.fpga.rate_apply, cnc::fpga::RateApply::Immediately);
    EXPECT_EQ(c.planner.mode, cnc::host::planner::BlendMode::Continuous);
    EXPECT_EQ(c.planner.profile, cnc::host::planner::Profile::Trapezoidal);
    EXPECT_DOUBLE_EQ(c.planner.x.max_accel_mm_per_s2, 1000.0);
    EXPECT_DOUBLE_EQ(c.planner.path_tolerance_mm, 0.05);
}

TEST(SpiFpgaSettings, SetOnTheCommandLineOverridesTheKeys) {
    const auto s = cnc::sim::load_scenario(
        write_scenario("cli", kJob),
        {"host.servo_period_us=500", "host.latency_max_us=80", "planner.mode=\"exact-stop\"",
         "fpga_spi.rate_apply=\"at-next-pulse\"", "machine.y.max_velocity_mm_per_s=50", "spi.sclk_hz=2500000"});
    EXPECT_EQ(s.settings<cnc::sim::SpiFpgaSettings>().servo.period_ps, 500 * kPsPerUs);
    EXPECT_EQ(s.settings<cnc::sim::SpiFpgaSettings>().servo.latency.max_ps, 80 * kPsPerUs);
    EXPECT_EQ(s.settings<cnc::sim::SpiFpgaSettings>().planner.mode, cnc::host::planner::BlendMode::ExactStop);
    EXPECT_EQ(s.settings<cnc::sim::SpiFpgaSettings>().fpga.rate_apply, cnc::fpga::RateApply::AtNextPulse);
    EXPECT_DOUBLE_EQ(s.settings<cnc::sim::SpiFpgaSettings>().planner.y.max_velocity_mm_per_s, 50.0);
    EXPECT_EQ(s.settings<cnc::sim::SpiFpgaSettings>().link.sclk_hz, 2'500'000U);
}

TEST(SpiFpgaSettings, EveryKeyIsDocumentedAndNoneClashesWithFpgaUart) {
    const auto keys = cnc::sim::scenario_keys();
    const auto has = [&](const std::string& k) {
        return std::count_if(keys.begin(), keys.end(), [&](const cnc::sim::KeyDoc& d) { return d.key == k; });
    };
    for (const char* k : {"machine.x.max_velocity_mm_per_s",
                          "machine.y.max_accel_mm_per_s2",
                          "machine.x.max_jerk_mm_per_s3",
                          "planner.profile",
                          "planner.mode",
                          "planner.path_tolerance_mm",
                          "planner.lookahead_moves",
                          "host.servo_period_us",
                          "host.latency_max_us",
                          "host.latency_distribution",
                          "host.position_gain",
                          "host.deadband_steps",
                          "host.stepgen_margin",
                          "spi.sclk_hz",
                          "spi.cs_setup_ns",
                          "spi.cs_hold_ns",
                          "spi.trace_wires",
                          "fpga_spi.fifo_depth",
                          "fpga_spi.pulse_cycles",
                          "fpga_spi.dir_setup_cycles",
                          "fpga_spi.dir_hold_cycles",
                          "fpga_spi.rate_apply",
                          "fpga_spi.clock_hz"}) {
        EXPECT_EQ(has(k), 1) << k;
    }
}

TEST(SpiFpgaSettings, AccelerationZeroIsRefusedWithItsLine) {
    const std::string e = load_error(std::string(kJob) + "[machine.x]\nmax_accel_mm_per_s2 = 0\n");
    EXPECT_NE(e.find(".toml:5: machine.x.max_accel_mm_per_s2: must be > 0"), std::string::npos) << e;
}

TEST(SpiFpgaSettings, AServoPeriodShorterThanTheTransferIsRefused) {
    // 72 bits at 5 MHz + 2 x 1 us = 16.4 us with SS low, 17.4 us with the SS-high gap
    const std::string e = load_error(std::string(kJob) + "[host]\nservo_period_us = 17\n");
    EXPECT_NE(e.find(".toml:5: host.servo_period_us: a 72-bit frame at 5000000 Hz takes 16.4 us"), std::string::npos)
        << e;
    EXPECT_NE(e.find("17.4 us with the SS-high gap, more than the 17 us servo period"), std::string::npos) << e;
    // exactly one slot fits (latency 0)
    EXPECT_EQ(load_error(kJob, {"host.servo_period_us=17.4", "host.latency_max_us=0"}), "");
}

TEST(SpiFpgaSettings, ALatencyLargerThanThePeriodIsRefused) {
    const std::string e = load_error(kJob, {"host.latency_max_us=1000"});
    // set by --set, so named as such
    EXPECT_NE(e.find("--set host.latency_max_us: a wake-up latency of up to 1000 us plus the 17.4 us SPI"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("below the period minus the transfer (982.6 us)"), std::string::npos) << e;
    EXPECT_EQ(load_error(kJob, {"host.latency_max_us=982.6"}), "");
}

TEST(SpiFpgaSettings, ALinkTheOversamplingSlaveCannotFollowIsRefused) {
    const std::string e = load_error(kJob, {"spi.sclk_hz=8400000"});
    EXPECT_NE(e.find("spi.sclk_hz: spi: sclk_hz: SCLK 8400000 Hz is too fast"), std::string::npos) << e;
    EXPECT_NE(e.find("the highest usable rate is 8333194 Hz"), std::string::npos) << e;
    EXPECT_EQ(load_error(kJob, {"spi.sclk_hz=8333194"}), "");
}
