// Documented numbers of the spi-fpga link and FPGA (models/spi/README.md, models/fpga/spi/README.md) and the
// seed 004 §5.2 verification waveform.
#include <gtest/gtest.h>

#include <vector>

#include "fpga/spi/core/pulse_gen_core.hpp"
#include "fpga/spi/core/spi_fpga_config.hpp"
#include "spi/core/spi_frame.hpp"
#include "spi/core/spi_timing.hpp"

namespace cnc {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(SpiGolden, WorkedCommandFrame) {
    // +10 000 steps/s and -1 600 steps/s at 50 MHz: periods 5000 and 31 250 clocks.
    const std::uint32_t min_period = fpga::min_period_cycles(fpga::SpiFpgaConfig{});
    const auto x = spi::axis_rate_for(10'000.0, 50'000'000, min_period);
    const auto y = spi::axis_rate_for(-1'600.0, 50'000'000, min_period);
    EXPECT_EQ(spi::encode_command({{x, y}}, min_period), (Bytes{0x52, 0x80, 0x00, 0x13, 0x88, 0x00, 0x00, 0x7A, 0x12}));
}

TEST(SpiGolden, WorkedCommandFrameWithTheLaserOn) {
    // The same rates with the laser on: X word = 0x8000'0000 (DIR) | 0x4000'0000 (laser) | 5000 (0x1388)
    // = 0xC000'1388; the Y word is unchanged (its bit 30 is reserved, sent 0).
    const std::uint32_t min_period = fpga::min_period_cycles(fpga::SpiFpgaConfig{});
    const spi::Command c{{{5'000, true}, {31'250, false}}, true};
    const Bytes golden{0x52, 0xC0, 0x00, 0x13, 0x88, 0x00, 0x00, 0x7A, 0x12};
    EXPECT_EQ(spi::encode_command(c, min_period), golden);
    EXPECT_EQ(spi::decode_command(golden, 2), c);
}

TEST(SpiGolden, WorkedFeedbackFrame) {
    spi::Feedback f;
    f.status.fifo_level = 1;
    f.counts = {1234, -2};
    EXPECT_EQ(spi::encode_feedback(f), (Bytes{0x81, 0x00, 0x00, 0x04, 0xD2, 0xFF, 0xFF, 0xFF, 0xFE}));
}

TEST(SpiGolden, DefaultLinkBudget) {
    const spi::SpiConfig link;
    EXPECT_EQ(spi::frame_bits(2), 72U);
    EXPECT_EQ(spi::transfer_time_ps(link, 72), 16'400'000);  // 16.4 us with SS low
    EXPECT_EQ(spi::transfer_slot_ps(link, 72), 17'400'000);  // 1.74 % of a 1 ms servo period
    EXPECT_EQ(fpga::max_sclk_hz(fpga::SpiFpgaConfig{}), 8'333'194U);
}

TEST(SpiGolden, RateLimitsAtFiftyMegahertz) {
    const std::uint32_t min_period = fpga::min_period_cycles(fpga::SpiFpgaConfig{});
    EXPECT_EQ(min_period, 101U);
    EXPECT_NEAR(spi::rate_for_period(min_period, 50'000'000), 495'049.5, 0.1);
    // 2^30 - 1 clocks: 50e6 / 1,073,741,823 = 0.046566 steps/s, one step in 21.47 s.
    EXPECT_EQ(spi::kMaxPeriodCycles, 1'073'741'823U);
    EXPECT_NEAR(spi::rate_for_period(spi::kMaxPeriodCycles, 50'000'000), 0.046566, 1e-6);
}

TEST(SpiGolden, Seed004Fig52PulsesEveryTenPlusOneClocksForTwo) {
    // §5.2: pulsegen(frequency = 10, duration = 2) -> a 2-clock pulse every 11 clocks; here the word is the
    // period between rises, so the same waveform is period 11 with pulse_cycles = 2.
    fpga::SpiFpgaConfig cfg;
    cfg.pulse_cycles = 2;
    fpga::PulseGenCore g(cfg);
    (void)g.load(0, {11, false});
    std::vector<std::int64_t> rises;
    std::vector<std::int64_t> falls;
    for (auto c = g.next_change(); c && c->edge < 34; c = g.next_change()) {
        (c->level ? rises : falls).push_back(c->edge);
        g.pop();
    }
    EXPECT_EQ(rises, (std::vector<std::int64_t>{0, 11, 22, 33}));
    EXPECT_EQ(falls, (std::vector<std::int64_t>{2, 13, 24}));
}

}  // namespace
}  // namespace cnc
