// Seed 000 numbers through the SystemC-free cores: worked packet encodings, NUMERATOR/feed periods, the
// §3.4.7 example, the 32-bit period overflow, and the cycle timeline of models/fpga/README.md.
#include <gtest/gtest.h>

#include <cmath>

#include "common/units.hpp"
#include "fpga/core/packet_decoder_core.hpp"
#include "fpga/core/step_schedule.hpp"
#include "fpga/core/uart_timing.hpp"
#include "uart_wave.hpp"

namespace cnc::fpga {
namespace {

TEST(Seed000Golden, WorkedEncodingsDecode) {
    EXPECT_EQ(test::init_packet(18'750'000, 18'750'000),
              (std::vector<std::uint8_t>{0xFF, 0x01, 0x1E, 0x1A, 0x30, 0x01, 0x1E, 0x1A, 0x30}));
    const std::vector<std::uint8_t> motion{0x01, 0x00, 0x00, 0x01, 0x40, 0xFF, 0xFF, 0xFF, 0x60, 0x04, 0xB0};
    EXPECT_EQ(test::motion_packet(1, 320, -160, 1200), motion);
    PacketDecoderCore d(18'750'000);
    for (std::size_t i = 0; i + 1 < motion.size(); ++i) {
        EXPECT_EQ(d.on_byte(motion[i]), PacketDecoderCore::Completed::None);
    }
    EXPECT_EQ(d.on_byte(motion.back()), PacketDecoderCore::Completed::Motion);
    EXPECT_EQ(d.motion().motion, 1);
    EXPECT_EQ(d.motion().steps_x, 320);
    EXPECT_EQ(d.motion().steps_y, -160);
    EXPECT_EQ(d.motion().feed, 1200);
}

TEST(Seed000Golden, WorkedExamplePeriodsAndTimeline) {
    const FpgaConfig cfg;
    const StepSchedule s({320, -160, 1200, 18'750'000, 18'750'000}, false, false, cfg);
    EXPECT_EQ(s.periods().x_cycles, 15'625U);  // 312.5 us
    EXPECT_EQ(s.periods().y_cycles, 31'250U);
    EXPECT_EQ(cycles_to_ps(15'625, cfg.clk_hz), 312'500'000);
    EXPECT_EQ(s.run_start(), 203);                           // §5.2.4: RUN starts at k+203
    EXPECT_EQ(s.run_start() - StepSchedule::kDirEdge, 201);  // DIR -> first STEP: 4.02 us >= 4 us
    EXPECT_EQ(s.run_cycles(), 320LL * 15'625);
    EXPECT_EQ(s.busy_fall(), 203 + 5'000'000);  // DONE at k+203+N
}

TEST(Seed000Golden, Section347FeedExample) {
    // §3.4.7: the RTL receives feed 894 (not the 894.43 the text computes with) for 1600 x 800 steps.
    const FpgaConfig cfg;
    const StepPeriods p = compute_periods(1600, 800, 894, 18'750'000, 18'750'000, cfg);
    EXPECT_EQ(p.x_cycles, 20'973U);
    EXPECT_EQ(p.y_cycles, 41'946U);
    const StepSchedule s({1600, 800, 894, 18'750'000, 18'750'000}, true, true, cfg);
    EXPECT_EQ(s.run_cycles(), 1600LL * 20'973);  // 33,556,800 cycles = 671.136 ms
}

TEST(Seed000Golden, Q3OverflowAtFeed100And73600Steps) {
    // 460 mm at 160 steps/mm and 100 mm/min: (18,750,000/100) * 73,600 = 1.38e10 > 2^32-1.
    FpgaConfig wrap;
    wrap.period_arithmetic = PeriodArithmetic::Wrap32;
    const StepPeriods exact = compute_periods(73'600, 36'800, 100, 18'750'000, 18'750'000, FpgaConfig{});
    const StepPeriods wrapped = compute_periods(73'600, 36'800, 100, 18'750'000, 18'750'000, wrap);
    EXPECT_TRUE(exact.overflow);
    EXPECT_EQ(exact.y_cycles, 375'000U);
    EXPECT_EQ(wrapped.y_cycles, 24'866U);
}

TEST(Seed000Golden, PulseSettleFeedZeroAndAckDurations) {
    const FpgaConfig cfg;
    EXPECT_EQ(cycles_to_ps(cfg.pulse_high_cycles, cfg.clk_hz), 2 * kPsPerUs);            // STEP high 2 us
    EXPECT_EQ(cycles_to_ps(cfg.dir_settle_cycles, cfg.clk_hz), 4 * kPsPerUs);            // DIR_SETTLE 4 us
    EXPECT_EQ(cycles_to_ps(cfg.feed_zero_period_cycles, cfg.clk_hz), 1'250 * kPsPerUs);  // 1.25 ms per step
    EXPECT_EQ(cycles_to_ps(cfg.watchdog_cycles, cfg.clk_hz), 100 * kPsPerMs);            // 100 ms watchdog
    const UartTxFrame ack = uart_tx_frame(0xAA, cfg);
    EXPECT_EQ(ack.idle_from - 2, 4'340);  // start bit to end of stop bit: 86.8 us on the wire
    EXPECT_EQ(cycles_to_ps(4'340, cfg.clk_hz), 86'800'000);
}

}  // namespace
}  // namespace cnc::fpga

namespace cnc::fpga {
namespace {

// seed 000 §5.2.4 NUMERATOR_DEFAULT, the reset value of num_x/num_y: clock x 60 s/min / steps per mm, so that the
// dominant period num / F cycles steps at exactly F mm/min. With the thesis's 50 MHz CLOCK_50 (§5.1.1) and
// 160 steps/mm (GT2 20T = 40 mm per 200 x 32 microsteps, §3.4.2): 50e6 x 60 / 160 = 18,750,000. Worked here from
// those numbers, not read from the config: a move of 160 steps at F600 lasts 100 ms (1 mm at 10 mm/s).
TEST(Seed000Golden, ResetNumeratorStepsAtTheProgrammedFeedFor160StepsPerMm) {
    const FpgaConfig cfg;
    const std::uint32_t steps_per_mm = 200 * 32 / 40;
    ASSERT_EQ(steps_per_mm, 160U);
    EXPECT_EQ(cfg.numerator_default, 50'000'000U * 60U / steps_per_mm);
    EXPECT_EQ(cfg.clk_hz, 50'000'000U);
    const StepPeriods p = compute_periods(160, 0, 600, cfg.numerator_default, cfg.numerator_default, cfg);
    EXPECT_EQ(p.x_cycles, 31'250U);  // 625 us between steps: 1,600 steps/s = 10 mm/s
    EXPECT_EQ(run_duration_ps({160, 0, 600, cfg.numerator_default, cfg.numerator_default}, cfg), 100 * kPsPerMs);
    // The UART divisor of the same clock (§5.2.1): FULL_BIT = round(50 MHz / 115200) = 434, HALF_BIT = 217.
    EXPECT_EQ(cfg.uart_full_bit_cycles, static_cast<std::uint32_t>(std::lround(50e6 / 115'200.0)));
    EXPECT_EQ(cfg.uart_half_bit_cycles, cfg.uart_full_bit_cycles / 2);
}

}  // namespace
}  // namespace cnc::fpga
