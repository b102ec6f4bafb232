// Whole fpga-uart runs against the seed 000 numbers. The tests that work a position out of
// step counts set mechanics.model=ideal: a carriage that moves one microstep per step, so step_gen's staircase
// alone decides where the tool is.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "fpga_uart_test_util.hpp"
#include "support/bad_input_message.hpp"
#include "uart/core/line_receiver.hpp"

using cnc::TimePs;
using cnc::test::bad_input_message;
using cnc::test::periods;
using cnc::test::run_shipped;

namespace {
constexpr TimePs kClockPs = 20'000;  // 50 MHz

// The circle of circle_r10.nc (radius 10 mm about (10, 10), G2 at F600 from (20, 10)) as step_gen draws it, rebuilt
// from seed 000's arithmetic, so that the contour error is derived without the CAM's feeds, step_gen or the
// metrics. The chords are the packets' step counts; per chord:
//   - the packet feed is F x dominant / length, rounded (§3.4.5), at 160 steps/mm on both axes;
//   - the dominant period is NUMERATOR / feed, NUMERATOR = 50 MHz x 60 s / 160 steps/mm = 18 750 000, and the other
//     axis's is that x N_dominant / N_other, both truncated to clocks (§5.2.4);
//   - step_gen fires both axes on the first RUN clock and then once a period: step k of an axis at k periods,
//     k = 0 .. N - 1, and steps of both axes at the same clock move the tool together.
// The contour error of the tool after each step event is | |p - c| - R |. (The G0 before the circle, along
// (2, 1), leads its line by under one step across it: < 6.25 um x 2 / sqrt(5) = 5.59 um, below the circle's.)
double circle_staircase_contour_max_um(const nlohmann::json& packets) {
    constexpr double kStepsPerMm = 160.0;
    constexpr std::int64_t kNumerator = 18'750'000;
    constexpr double kFeedMmPerMin = 600.0;
    const double cx = 10.0 * kStepsPerMm, cy = 10.0 * kStepsPerMm, r = 10.0 * kStepsPerMm;  // in steps
    std::int64_t x = 0, y = 0;
    double worst_steps = 0.0;
    for (const auto& p : packets) {
        const std::int64_t sx = p.at("steps").at(0), sy = p.at("steps").at(1);
        const std::int64_t nx = std::llabs(sx), ny = std::llabs(sy);
        const bool arc = p.at("motion") != 0;
        if (arc) {
            const std::int64_t n_dom = std::max(nx, ny), n_sub = std::min(nx, ny);
            const auto feed = std::llround(kFeedMmPerMin * static_cast<double>(n_dom) / std::hypot(nx, ny));
            const std::int64_t p_dom = kNumerator / feed;
            const std::int64_t p_sub = n_sub > 0 ? p_dom * n_dom / n_sub : 0;
            EXPECT_EQ(p.at("feed"), feed);
            EXPECT_EQ(p.at("period_cycles"), nlohmann::json(nx >= ny ? std::vector<std::int64_t>{p_dom, p_sub}
                                                                     : std::vector<std::int64_t>{p_sub, p_dom}));
            const std::int64_t px = nx >= ny ? p_dom : p_sub, py = nx >= ny ? p_sub : p_dom;
            std::int64_t kx = 0, ky = 0;  // steps made
            while (kx < nx || ky < ny) {
                const std::int64_t tx = kx < nx ? kx * px : INT64_MAX, ty = ky < ny ? ky * py : INT64_MAX;
                const std::int64_t t = std::min(tx, ty);
                if (tx == t) ++kx;
                if (ty == t) ++ky;
                const double dx = static_cast<double>(x + (sx < 0 ? -kx : kx)) - cx;
                const double dy = static_cast<double>(y + (sy < 0 ? -ky : ky)) - cy;
                worst_steps = std::max(worst_steps, std::fabs(std::hypot(dx, dy) - r));
            }
        }
        x += sx;
        y += sy;
    }
    return worst_steps / kStepsPerMm * 1000.0;
}
}  // namespace

// The packet 01 00 00 01 40 FF FF FF 60 04 B0 on the real chain.
TEST(FpgaUartWorkedExample, StepTrainsDirSetupAckAndLaser) {
    const auto out = run_shipped("worked_example", {}, true);
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& x = out.arch.input.axes[0];
    const auto& y = out.arch.input.axes[1];
    const auto xr = x.step.rising();
    const auto yr = y.step.rising();
    ASSERT_EQ(xr.size(), 320U);
    ASSERT_EQ(yr.size(), 160U);
    for (TimePs d : periods(xr)) ASSERT_EQ(d, 15'625 * kClockPs);  // 312.5 us
    for (TimePs d : periods(yr)) ASSERT_EQ(d, 31'250 * kClockPs);
    EXPECT_EQ(xr.front(), yr.front());  // both axes fire on the first RUN cycle
    for (const auto* axis : {&x, &y}) {
        const auto r = axis->step.rising();
        const auto f = axis->step.falling();
        ASSERT_EQ(r.size(), f.size());
        for (std::size_t i = 0; i < r.size(); ++i) ASSERT_EQ(f[i] - r[i], 100 * kClockPs);  // 2.000 us high
    }
    // DIR: X positive (DIR=1) set in SETUP, 201 clocks (4.02 us) before the first STEP; Y negative stays 0.
    ASSERT_EQ(x.dir.edges.size(), 1U);
    EXPECT_TRUE(x.dir.edges[0].level);
    EXPECT_EQ(xr.front() - x.dir.edges[0].t_ps, 201 * kClockPs);
    EXPECT_GE(xr.front() - x.dir.edges[0].t_ps, 4 * cnc::kPsPerUs);
    EXPECT_TRUE(y.dir.edges.empty());
    EXPECT_FALSE(y.dir.level_at(yr.front()));

    // busy and laser: the laser follows busy one clock later, and is on only while busy.
    const auto& busy = out.arch.lines.at("busy");
    ASSERT_EQ(busy.rising().size(), 1U);
    ASSERT_EQ(busy.falling().size(), 1U);
    const TimePs busy_rise = busy.rising()[0];
    const TimePs busy_fall = busy.falling()[0];
    const TimePs last_period_end = xr.back() + 15'625 * kClockPs;
    EXPECT_EQ(busy_fall, last_period_end);  // DONE: the edge after the last RUN cycle (seed 000 §5.2.4: k+203+N)
    const auto& laser = *out.arch.input.laser;
    ASSERT_EQ(laser.rising().size(), 1U);
    ASSERT_EQ(laser.falling().size(), 1U);
    EXPECT_EQ(laser.rising()[0], busy_rise + kClockPs);
    EXPECT_EQ(laser.falling()[0], busy_fall + kClockPs);

    // The ACK byte on the FPGA's tx line, decoded at the FPGA's 434-clock bit, after the last period.
    const auto& tx = out.arch.lines.at("uart_tx");
    const auto starts = tx.falling();
    ASSERT_FALSE(starts.empty());
    EXPECT_GT(starts.front(), last_period_end);
    EXPECT_EQ(starts.front(), busy_fall + 3 * kClockPs);  // top: tx_start +1, uart_tx: busy +2, start bit +3
    const cnc::uart::BitClock fpga_bit{434, 50'000'000};
    const auto frame = cnc::uart::receive_frame(tx, starts.front(), fpga_bit, cnc::uart::kFormat8N1);
    EXPECT_EQ(frame.status, cnc::uart::RxStatus::Ok);
    EXPECT_EQ(frame.byte, 0xAA);
    EXPECT_EQ(frame.t_stop_end_ps, starts.front() + 4'340 * kClockPs);     // 10 bits of 434 clocks: 86.8 us
    EXPECT_EQ(tx.edges.back().t_ps, starts.front() + 8 * 434 * kClockPs);  // d7 = 1: high from bit 8 on
    EXPECT_EQ(starts.size(), 4U);  // 0xAA LSB first: the start bit and three 1->0 data transitions: one byte
}

// The six segments of the thesis's log: motion time from the cycle model, and the dead time parts.
TEST(FpgaUartSixSegment, MotionTimeAndDeadTimeBreakdown) {
    const auto out = run_shipped("six_segment");
    ASSERT_TRUE(out.ok) << out.failure;
    // sum of dominant steps x NUMERATOR/feed clocks: 17.171694 s (17.17 s worked out from the log of seed 000 §6.3.1)
    const double expected_s =
        (15889.0 * 15625 + 8000.0 * 23437 + 5034.0 * 15625 + 4132.0 * 23437 + 6829.0 * 15625 + 6000.0 * 23437) * 20e-9;
    ASSERT_TRUE(out.metrics.timing.motion_time_s.has_value());
    EXPECT_NEAR(*out.metrics.timing.motion_time_s, 17.1717, 17.1717 * 1e-4);
    EXPECT_NEAR(*out.metrics.timing.motion_time_s, expected_s, 1e-9);
    const auto& dead = out.report.at("fpga-uart").at("dead_time");
    EXPECT_EQ(dead.at("gaps"), 5);
    const auto& mean = dead.at("mean");
    // 11 frames of 10 bits at the CP2102's 24 MHz / 208 = 115 384.6 Bd, the last one only until uart_rx samples its
    // stop bit, 9.5 of its 434-clock bits (20 ns clocks) after the start edge: 0.86667 + 0.08246 = 0.94913 ms; the
    // two-flip-flop synchroniser on the start edge adds clocks, not microseconds.
    const double packet_wire_ms = (10.0 * 10.0 / (24e6 / 208.0) + 9.5 * 434 * 20e-9) * 1e3;
    EXPECT_NEAR(mean.at("packet_wire_ms").get<double>(), packet_wire_ms, 0.0005);
    // tx_start one clock after the busy fall, then 10 bits of 434 clocks: 86.8 us
    EXPECT_NEAR(mean.at("ack_wire_ms").get<double>(), 0.0868, 0.0001);
    EXPECT_GE(mean.at("usb_in_ms").get<double>(), 1.0);  // link.usb_latency_ms plus the wait for a USB frame
    EXPECT_LE(mean.at("usb_in_ms").get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(mean.at("host_ms").get<double>(), 0.2);  // host.packet_processing_us
    double parts = 0.0;
    for (const char* p :
         {"step_tail_ms", "ack_wire_ms", "usb_in_ms", "host_ms", "usb_out_ms", "packet_wire_ms", "fpga_setup_ms"}) {
        parts += mean.at(p).get<double>();
    }
    EXPECT_NEAR(parts, mean.at("total_ms").get<double>(), 1e-9);
    EXPECT_NEAR(mean.at("total_ms").get<double>(), *out.metrics.timing.dead_mean_ms, 1e-9);
}

// A period counter on a 50 MHz clock scores at most one clock of TIE on every constant-rate run.
class FpgaUartTie : public ::testing::TestWithParam<const char*> {};

TEST_P(FpgaUartTie, TieMaxWithinOneClock) {
    const auto out = run_shipped(GetParam());
    ASSERT_TRUE(out.ok) << out.failure;
    ASSERT_TRUE(out.metrics.pulse.tie_max_ns.has_value());
    EXPECT_LE(*out.metrics.pulse.tie_max_ns, 20.0);
    // The runs themselves are listed only with --detail; their summary counts them.
    EXPECT_GT(out.metrics.axes[0].pulse.runs + out.metrics.axes[1].pulse.runs, 0U);
}

INSTANTIATE_TEST_SUITE_P(Scenarios, FpgaUartTie,
                         ::testing::Values("worked_example", "worked_347", "six_segment", "square_20mm", "diagonal_45",
                                           "circle_r10"));

// Seed 000 §3.4.7: G1 X10 Y5 F1000 from the origin at 160 steps/mm.
TEST(FpgaUartWorked347, StepsFeedPeriodsMoveTimeAndResultantFeed) {
    const auto out = run_shipped("worked_347", {"trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& p = out.report.at("fpga-uart").at("fpga").at("packets").at(0);
    EXPECT_EQ(p.at("steps"), nlohmann::json({1600, 800}));
    EXPECT_EQ(p.at("feed"), 894);
    EXPECT_EQ(p.at("period_cycles"), nlohmann::json({20'973, 41'946}));
    const auto& move = out.metrics.moves.at(0);
    ASSERT_TRUE(move.timing.motion_time_s.has_value());
    EXPECT_DOUBLE_EQ(*move.timing.motion_time_s, 1600.0 * 20'973 * 20e-9);  // 0.671136 s
    EXPECT_NEAR(*move.timing.motion_time_s, 0.6711, 5e-5);
    ASSERT_TRUE(move.timing.achieved_feed_mm_per_min.has_value());
    EXPECT_NEAR(*move.timing.achieved_feed_mm_per_min, 999.5, 0.05);
    EXPECT_NEAR(*move.timing.feed_error_pct, (std::sqrt(125.0) / 0.671136 * 60 / 1000 - 1) * 100, 1e-9);
}

// The same arithmetic on the 45° diagonal: the packet feed 1000/sqrt(2) = 707.1 -> 707 and the period
// 18,750,000 / 707 = 26,520.5 -> 26,520 clocks leave a feed error the metrics must show.
TEST(FpgaUartDiagonal, FeedErrorOfTheIntegerFeedAndTruncatedPeriod) {
    const auto out = run_shipped("diagonal_45", {"trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& p = out.report.at("fpga-uart").at("fpga").at("packets").at(0);
    EXPECT_EQ(p.at("feed"), 707);
    EXPECT_EQ(p.at("period_cycles"), nlohmann::json({26'520, 26'520}));
    const double time_s = 3200.0 * 26'520 * 20e-9;
    const double achieved = std::hypot(20.0, 20.0) / time_s * 60.0;
    const auto& move = out.metrics.moves.at(0);
    EXPECT_NEAR(*move.timing.achieved_feed_mm_per_min, achieved, 1e-6);
    EXPECT_NEAR(*move.timing.feed_error_pct, (achieved / 1000.0 - 1.0) * 100.0, 1e-6);
    EXPECT_LT(*move.timing.feed_error_pct, 0.0);  // 707 < 707.1: slower than programmed
}

// The circle's contour error stays within the chord tolerance plus one step, and is what the staircase
// of step_gen over the chords gives (7.796 um, on four chords, one per quadrant).
TEST(FpgaUartCircle, ContourErrorWithinChordTolerancePlusOneStep) {
    const auto out = run_shipped("circle_r10", {"mechanics.model=ideal", "trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    ASSERT_TRUE(out.metrics.path.contour_max_um.has_value());
    ASSERT_TRUE(out.metrics.path.contour_rms_um.has_value());
    EXPECT_LE(*out.metrics.path.contour_max_um, 2.0 + 6.25);
    EXPECT_NEAR(*out.metrics.path.contour_max_um,
                circle_staircase_contour_max_um(out.report.at("fpga-uart").at("fpga").at("packets")), 1e-6);
    EXPECT_GT(*out.metrics.path.contour_rms_um, 0.0);
    EXPECT_LT(*out.metrics.path.contour_rms_um, *out.metrics.path.contour_max_um);
    EXPECT_GT(out.metrics.pieces.size(), 100U);  // the circle went as chords
    EXPECT_EQ(out.metrics.moves.size(), 2U);     // of two programmed moves: the G0 and the circle
}

// The seed's literal chord-end rounding (each axis rounded, §3.4.4) leaves the chord ends up to 0.71 step off the
// circle: with the step_gen staircase the contour error then exceeds tolerance + one step (9.641 um), within the
// bound that adds the ends' rounding: 2 + 6.25 + 6.25 x sqrt(2) / 2 = 12.67 um.
TEST(FpgaUartCircle, SeedRoundingOfChordEndsExceedsTheBound) {
    const auto out = run_shipped("circle_r10", {"host.chord_ends=round", "mechanics.model=ideal", "trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    EXPECT_NEAR(*out.metrics.path.contour_max_um,
                circle_staircase_contour_max_um(out.report.at("fpga-uart").at("fpga").at("packets")), 1e-6);
    EXPECT_GT(*out.metrics.path.contour_max_um, 2.0 + 6.25);
    EXPECT_LE(*out.metrics.path.contour_max_um, 2.0 + 6.25 + 6.25 * std::sqrt(2.0) / 2.0);
    EXPECT_EQ(out.report.at("fpga-uart").at("segments"), 159);
}

// The appendix step_gen's 32-bit period product: 187,500 clocks x 73,600 steps = 1.38e10 does not fit.
TEST(FpgaUartOverflow, ExactPeriodByDefaultAndAWarning) {
    const auto out = run_shipped("overflow_slow_diagonal", {"mechanics.model=ideal", "trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& p = out.report.at("fpga-uart").at("fpga").at("packets").at(0);
    EXPECT_EQ(p.at("period_cycles"), nlohmann::json({187'500, 8'625'000}));  // 187,500 x 73,600 / 1,600
    EXPECT_TRUE(p.at("period_overflow").get<bool>());
    ASSERT_EQ(out.arch.warnings.size(), 1U);
    EXPECT_EQ(out.arch.warnings[0].kind, "period_overflow");
    EXPECT_EQ(out.arch.warnings[0].where, "segment 1 (line 5)");
    EXPECT_NE(out.arch.warnings[0].text.find("exceeds 32 bits"), std::string::npos);
    EXPECT_LE(*out.metrics.path.contour_max_um, 6.25);
}

TEST(FpgaUartOverflow, Wrap32ReproducesTheAppendixRtl) {
    const auto out = run_shipped("overflow_slow_diagonal", {"fpga.period_arithmetic=wrap32", "trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& p = out.report.at("fpga-uart").at("fpga").at("packets").at(0);
    // (13,800,000,000 mod 2^32) / 1,600 = 915,098,112 / 1,600 -> 571,936: Y finishes after 0.9 s of 276 s
    EXPECT_EQ(p.at("period_cycles"), nlohmann::json({187'500, 571'936}));
    EXPECT_GT(*out.metrics.path.contour_max_um, 9'000.0);  // the tool leaves the line by 9 mm
    EXPECT_NE(out.arch.warnings.at(0).text.find("used the wrapped period"), std::string::npos);
}

// A 12 s move against send_steps.py's 10 s ACK timeout.
TEST(FpgaUartLongMove, SeedFaithfulSenderReportsAckTimeout) {
    const auto out = run_shipped("long_move_timeout", {"trace.detail=true"});
    EXPECT_FALSE(out.ok);
    const auto& sender = out.report.at("fpga-uart").at("sender");
    EXPECT_EQ(sender.at("errors"), 1);
    EXPECT_TRUE(sender.at("aborted").get<bool>());
    const auto& sent = sender.at("packets").at(0);
    EXPECT_TRUE(sent.at("timed_out").get<bool>());
    const auto& msg = sender.at("messages").at(0);
    // long_move.nc line 4: G1 X100 F500 from the origin, 100 mm at 8.33 mm/s
    EXPECT_EQ(msg.at("text"),
              "[ERROR] seg 1 (G-code line 4, a 12.00 s move): no ACK within 10.0 s; raise host.ack_timeout_s above "
              "the longest move");
    EXPECT_EQ(out.failure,
              "ACK timeout at seg 1 (G-code line 4, a 12.00 s move): no ACK within 10.0 s; raise "
              "host.ack_timeout_s above the longest move; send_steps.py stops here (host.on_timeout = abort)");
    // the deadline starts when write() returns (after host.write_latency_us)
    EXPECT_NEAR(msg.at("t_s").get<double>(), sent.at("t_write_s").get<double>() + 100e-6 + 10.0, 1e-9);
    // the FPGA still finishes the 12 s move and sends its ACK, which nobody reads
    const auto& fpga = out.report.at("fpga-uart").at("fpga");
    EXPECT_EQ(fpga.at("acks_sent"), 1);
    EXPECT_NEAR(*out.metrics.moves.at(0).timing.motion_time_s, 16'000 * 37'500 * 20e-9, 1e-9);  // F500: 12 s
}

// A calibrated steps/mm reaches the CAM, the NUMERATOR and the carriage: X at 100 and Y at 50 steps/mm.
TEST(FpgaUartCalibratedMachine, StepsPerMmDrivesStepsAndCarriage) {
    const auto out = run_shipped(
        "worked_347",
        {"machine.x.steps_per_mm=100", "machine.y.steps_per_mm=50", "mechanics.model=ideal", "trace.detail=true"},
        true);
    ASSERT_TRUE(out.ok) << out.failure;
    EXPECT_EQ(out.arch.input.axes[0].step.rising().size(), 1'000U);       // 10 mm x 100
    EXPECT_EQ(out.arch.input.axes[1].step.rising().size(), 2U * 5 * 50);  // 5 mm out and back at 50
    // the carriage ends on the programmed (10, 0): the mechanics move 1/100 and 1/50 mm per microstep
    EXPECT_LT(*out.metrics.path.job_end_um, 1e-6);
    // The Y-only move at F1000: 16.67 mm/s x 50 steps/mm = 833.3 steps/s, 1.2 ms = 60,000 clocks at 50 MHz
    // (NUMERATOR_Y = 50 MHz x 60 / 50 = 60,000,000, divided by the feed; seed 000 §3.4.5).
    const auto& p = out.report.at("fpga-uart").at("fpga").at("packets");
    EXPECT_EQ(p.at(1).at("period_cycles").at(1), 60'000);
}

// A packet_decoder watchdog of 50 us, shorter than one byte at 115200 Bd (86.8 us), resets the decoder between
// every two bytes: the packet is lost, so the timeout is no help.
TEST(FpgaUartLongMove, TimeoutOfALostPacketSaysSo) {
    const auto out = run_shipped("diagonal_45", {"fpga.watchdog_ms=0.05"});
    EXPECT_FALSE(out.ok);
    // 20 mm on each axis at F1000: 28.28 mm at 16.67 mm/s, 1.70 s (line 4 of diagonal_45.nc)
    EXPECT_NE(out.failure.find("seg 1 (G-code line 4, a 1.70 s move): no ACK within 10.0 s, long after the move"),
              std::string::npos)
        << out.failure;
    EXPECT_NE(out.failure.find("the packet or its ACK was lost"), std::string::npos) << out.failure;
}

// A 57600 Bd line (CP2102: 24 MHz / 417 = 57 553.96 Bd) into the FPGA's 115200 Bd UART (50 MHz / 434 = 115 207.4
// Bd) is 50 % off: refused before the run, naming both keys (it used to run into framing errors and an ACK timeout).
TEST(FpgaUartLink, ABaudMismatchIsRefusedBeforeTheRun) {
    const std::string err = bad_input_message([] { (void)run_shipped("diagonal_45", {"link.baud=57600"}); });
    EXPECT_NE(err.find("diagonal_45.toml: link.baud, fpga.uart_baud: baud mismatch: link.baud = 57600 (the CP2102 "
                       "runs 57553.96 Bd) against the FPGA UART at 115207.37 Bd (fpga.uart_baud: 50 MHz / 434 clocks "
                       "a bit): the host's line runs -50.04 % off"),
              std::string::npos)
        << err;
    // +104 %: 235000 is in AN205's 230400 range (24 MHz / 104 = 230 769 Bd), twice the FPGA's rate
    EXPECT_NE(bad_input_message([] { (void)run_shipped("diagonal_45", {"link.baud=235000"}); }).find("+100.31 %"),
              std::string::npos);
}

// The 20 mm square's estimate: its moves at their feeds, send_steps.py's start-up and six packet trips.
TEST(FpgaUartEstimate, SquareEstimateAndDefaultLimit) {
    const auto out = run_shipped("square_20mm");
    ASSERT_TRUE(out.ok) << out.failure;
    // Two 14.14 mm rapids at 1200 mm/min and four 20 mm sides at F800; 0.3 s settle and 0.05 s after the init
    // packet; per packet 0.2 ms host work, 0.1 ms write latency, two 1 ms USB frames, 1 ms driver latency and
    // 12 bytes (packet and ACK) of 10 bits at 115200 Bd.
    const double trip_s = 0.2e-3 + 0.1e-3 + 2 * 1e-3 + 1e-3 + 12 * 10 / 115200.0;
    const double expected_s = 2 * std::sqrt(200.0) / 20.0 + 4 * 20.0 / (800.0 / 60.0) + 0.35 + 6 * trip_s;
    const auto& sc = out.report.at("scenario");
    EXPECT_NEAR(sc.at("estimated_s").get<double>(), expected_s, 1e-9);
    EXPECT_NEAR(sc.at("max_sim_s").get<double>(), 2 * expected_s + 6 * 1.0 + 10.0, 1e-9);
    // the run itself is within 0.1 % of it (the FPGA's integer periods and the USB frame phases)
    EXPECT_NEAR(out.metrics.timing.job_time_s, expected_s, 1e-3 * expected_s);
}

TEST(FpgaUartEstimate, ALimitSetInTheScenarioIsUsedAndNamed) {
    const auto out = run_shipped("square_20mm", {"scenario.max_sim_s=1"});
    EXPECT_FALSE(out.ok);
    EXPECT_EQ(out.report.at("scenario").at("max_sim_s"), 1.0);
    EXPECT_EQ(out.failure.rfind("the job did not finish: stopped at ", 0), 0U) << out.failure;
    EXPECT_NE(out.failure.find(" s of simulated time by scenario.max_sim_s = 1 s (this job's estimate: 7.790 s); "
                               "raise scenario.max_sim_s"),
              std::string::npos)
        << out.failure;
}

// The metrics stream by default (their inputs dropped as measured): the CLI's summary still lists them, the
// worst moves by G-code line included. The square's job: a rapid (line 3), the 4 sides at F800 (lines 5 to 8), a
// rapid home (line 10): 6 moves with tool samples, of which the 5 worst are listed; a feed error on the sides only.
TEST(FpgaUartStreamed, SummaryListsTheMetricsTables) {
    const auto out = run_shipped("square_20mm");
    ASSERT_TRUE(out.arch.input.axes.empty());  // streamed: no whole logs kept
    for (const char* section : {"Worst moves (move index, G-code line)", "Job timing", "Laser"}) {
        EXPECT_NE(out.summary.find(section), std::string::npos) << section;
    }
    EXPECT_EQ(out.metrics.worst.following.size(), cnc::metrics::kWorstMovesListed);
    std::vector<int> feed_lines;
    for (const cnc::metrics::RankedMove& r : out.metrics.worst.feed) feed_lines.push_back(r.line);
    std::sort(feed_lines.begin(), feed_lines.end());
    EXPECT_EQ(feed_lines, (std::vector<int>{5, 6, 7, 8}));
}
