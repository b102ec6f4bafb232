// Whole spi-fpga runs: servo thread -> SPI -> FPGA -> DRV8825 machine -> metrics.
// The checks that work a position out of step counts set mechanics.model=ideal: a carriage that moves one microstep
// per step, so the plan and the counts alone decide where the tool is.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "spi_fpga_test_util.hpp"

using cnc::kPsPerMs;
using cnc::kPsPerUs;
using cnc::TimePs;
using cnc::test::count_at;
using cnc::test::kClockPs;
using cnc::test::ps_of;
using cnc::test::run_spi;
using cnc::test::target_steps;

namespace {

// The edge at which the FPGA applies the frame whose SS rises at t (models/fpga/spi/README.md: sampled at the first
// edge after t, FrameEnd 2 edges later writes the FIFO, the generator reads it one edge later).
TimePs apply_time(TimePs t_ss_rise) {
    return (t_ss_rise / kClockPs + 1 + 2 + 1) * kClockPs;
}

}  // namespace

// Within each servo period the STEP train is the rate word's period exactly; words change only when a
// frame arrives (once per servo period); the cruise of a 3200 steps/s move is one word, 15,625 clocks.
TEST(SpiFpgaConstantRate, StepPeriodIsTheWordsPeriodAndChangesOnlyAtFrames) {
    // Exact stop: the move ramps at the whole 1000 mm/s^2 (in G64 the program's last move has half of it).
    const auto out = run_spi("long_x", {"trace.detail=true", "planner.mode=exact-stop"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& x = out.arch.input.axes[0];
    const std::vector<TimePs> rises = x.step.rising();
    ASSERT_EQ(rises.size(), 6400U);  // 40 mm
    const auto ss_rises = out.arch.lines.at("ss").rising();
    const auto& log = out.report["spi-fpga"]["rate_log"];
    const auto& words = log["axes"]["x"]["period_cycles"];
    // one transfer per period except the last (done)
    ASSERT_EQ(ss_rises.size() + 1, words.size());

    std::size_t checked_periods = 0;
    std::size_t k = 0;
    for (std::size_t n = 0; n < ss_rises.size(); ++n) {
        const TimePs from = apply_time(ss_rises[n]);
        const TimePs to = n + 1 < ss_rises.size() ? apply_time(ss_rises[n + 1]) : INT64_MAX;
        while (k < rises.size() && rises[k] < from) ++k;
        std::vector<TimePs> in_period;
        for (std::size_t j = k; j < rises.size() && rises[j] < to; ++j) in_period.push_back(rises[j]);
        const auto period = words[n].get<std::int64_t>();
        if (period == 0) {
            // a stop word: no rise after it takes effect (a pulse already high completes, but rises no more)
            ASSERT_TRUE(in_period.empty()) << "period " << n;
            continue;
        }
        for (std::size_t j = 1; j < in_period.size(); ++j) {
            ASSERT_EQ(in_period[j] - in_period[j - 1], static_cast<TimePs>(period) * kClockPs) << "period " << n;
        }
        checked_periods += in_period.size() >= 2 ? 1 : 0;
    }
    EXPECT_GT(checked_periods, 1900U);

    // The cruise: one word for at least 1.9 s (F1200 = 20 mm/s = 3200 steps/s = 15,625 clocks).
    std::size_t run = 0;
    std::size_t longest = 0;
    for (const auto& w : words) {
        run = w.get<std::int64_t>() == 15'625 ? run + 1 : 0;
        longest = std::max(longest, run);
    }
    EXPECT_GE(longest, 1900U);
    // The staircase of the acceleration: each of the first periods asks for 160 steps/s more (1000 mm/s^2).
    const auto& cmd = log["axes"]["x"]["commanded_steps_per_s"];
    EXPECT_NEAR(cmd[1].get<double>(), 80.0, 1e-6);
    EXPECT_NEAR(cmd[2].get<double>(), 240.0, 1e-6);
    EXPECT_NEAR(cmd[3].get<double>(), 400.0, 1e-6);
    EXPECT_EQ(words[1].get<std::int64_t>(), 625'000);  // 80 steps/s
    EXPECT_EQ(words[2].get<std::int64_t>(), 208'333);  // 240 steps/s
    // TIE of every run of one word: 0 (at most one clock is the check).
    ASSERT_TRUE(out.metrics.pulse.tie_max_ns.has_value());
    EXPECT_LE(*out.metrics.pulse.tie_max_ns, 20.0);
    EXPECT_EQ(*out.metrics.pulse.tie_max_ns, 0.0);
    EXPECT_EQ(*out.metrics.pulse.jitter_pp_max_ns, 0.0);
}

// Every transfer holds SS low for 72 bits / SCLK + cs_setup + cs_hold = 14.4 + 2 = 16.4 us, starting at
// the servo thread's wake-up; the report gives the same and its share of the period.
TEST(SpiFpgaTransfer, SsLowIsFrameBitsOverSclkPlusTheChipSelectGaps) {
    const auto out = run_spi("long_x", {"trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& ss = out.arch.lines.at("ss");
    const auto falls = ss.falling();
    const auto rises = ss.rising();
    ASSERT_EQ(falls.size(), rises.size());
    for (std::size_t i = 0; i < falls.size(); ++i) ASSERT_EQ(rises[i] - falls[i], 16'400'000) << i;
    const auto& t = out.report["spi-fpga"]["rate_log"]["t_s"];
    for (std::size_t i = 0; i < falls.size(); ++i) ASSERT_EQ(falls[i], ps_of(t[i].get<double>())) << i;
    // 72 SCLK pulses per frame
    EXPECT_EQ(out.arch.lines.at("sclk").rising().size(), 72 * falls.size());
    const auto& spi = out.report["spi-fpga"]["spi"];
    EXPECT_EQ(spi["frame_bits"].get<int>(), 72);
    EXPECT_DOUBLE_EQ(spi["transfer_us"].get<double>(), 16.4);
    EXPECT_DOUBLE_EQ(spi["slot_us"].get<double>(), 17.4);
    EXPECT_NEAR(spi["transfer_share_of_period_pct"].get<double>(), 1.64, 1e-12);
}

TEST(SpiFpgaTransfer, SlowerClockLongerTransfer) {
    // 1 MHz: 72 us of bits + 2 us of gaps
    const auto out = run_spi("long_x", {"spi.sclk_hz=1000000"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& ss = out.arch.lines.at("ss");
    const auto falls = ss.falling();
    const auto rises = ss.rising();
    ASSERT_FALSE(falls.empty());
    for (std::size_t i = 0; i < falls.size(); ++i) ASSERT_EQ(rises[i] - falls[i], 74 * kPsPerUs) << i;
    EXPECT_DOUBLE_EQ(out.report["spi-fpga"]["spi"]["transfer_us"].get<double>(), 74.0);
}

// Continuous mode crosses colinear joins at speed: no period at path speed 0 between start and end, and
// the gaps between moves are one STEP period; exact-stop comes to rest at each join.
TEST(SpiFpgaBlending, ContinuousHasNoDeadTimeBetweenColinearMoves) {
    const auto out = run_spi("colinear_x", {"trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& v = out.report["spi-fpga"]["velocity_log"]["path_speed_mm_per_s"];
    std::size_t first = 0;
    while (first < v.size() && v[first].get<double>() == 0.0) ++first;
    std::size_t last = v.size() - 1;
    while (last > 0 && v[last].get<double>() == 0.0) --last;
    for (std::size_t i = first; i <= last; ++i) ASSERT_GT(v[i].get<double>(), 0.0) << i;
    const auto gaps = cnc::metrics::dead_gaps(out.metrics.moves);
    ASSERT_EQ(gaps.size(), 2U);
    for (const auto& g : gaps) EXPECT_EQ(g.dead_ps, 15'625 * kClockPs);  // 3200 steps/s
    EXPECT_EQ(out.report["spi-fpga"]["servo"]["rest_points"].get<int>(), 1);
}

TEST(SpiFpgaBlending, ExactStopRestsAtEveryJoin) {
    const auto out = run_spi("colinear_x", {"planner.mode=\"exact-stop\"", "trace.detail=true"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& holds = out.report["spi-fpga"]["servo"]["holds"];
    ASSERT_EQ(holds.size(), 3U);
    const auto& log = out.report["spi-fpga"]["velocity_log"];
    const auto& t = log["t_s"];
    const auto& v = log["path_speed_mm_per_s"];
    for (const auto& h : holds) {
        // the velocity log shows 0 for every period of the hold
        const TimePs from = ps_of(h["t_first_s"].get<double>());
        const TimePs to = ps_of(h["t_release_s"].get<double>());
        std::size_t zeros = 0;
        for (std::size_t i = 0; i < t.size(); ++i) {
            const TimePs ti = ps_of(t[i].get<double>());
            if (ti >= from && ti < to) {
                EXPECT_EQ(v[i].get<double>(), 0.0);
                ++zeros;
            }
        }
        EXPECT_GE(zeros, 2U);
    }
    // the joins cost dead time: from the last step of a move to the first of the next, at least two periods
    const auto gaps = cnc::metrics::dead_gaps(out.metrics.moves);
    ASSERT_EQ(gaps.size(), 2U);
    for (const auto& g : gaps) EXPECT_GE(g.dead_ps, 2 * kPsPerMs);
}

TEST(SpiFpgaBlending, ContinuousCornersStayWithinTheBlendTolerance) {
    // The square's 90 degree corners blended within 0.05 mm of the corner: the tool stays within the tolerance
    // (on the 6.25 um step grid a job can in general land up to one step beyond it: six-segment reaches 54.3 um).
    const auto out = run_spi("square_20mm", {"mechanics.model=ideal"});
    ASSERT_TRUE(out.ok) << out.failure;
    EXPECT_LE(*out.metrics.path.contour_max_um, 50.0 + 1e-6);
    EXPECT_GT(*out.metrics.path.contour_max_um, 30.0);  // the blends do cut the corners (0.05 / sqrt 2 = 35 um)
}

TEST(SpiFpgaBlending, ExactStopCornersAreSharp) {
    const auto out = run_spi("square_exact_stop", {"mechanics.model=ideal"});
    ASSERT_TRUE(out.ok) << out.failure;
    EXPECT_LE(*out.metrics.path.contour_max_um, 6.25 * std::sqrt(2.0) + 1e-9);
}

// Closed loop. "End of a move": in exact-stop mode every move ends at a rest point, where the host holds
// its trajectory clock until each axis count equals the commanded position rounded to the step (the move's window
// ends at that release); in continuous mode the job end (and any reversal) is such a point. Asserted: the count of
// every axis at each exact-stop move's window end, and at the job end in both modes, equals the target, with exact
// wake-ups and with up to 200 us of latency.
struct LandingCase {
    const char* scenario;
    const char* mode;
    int latency_us;
};

void PrintTo(const LandingCase& c, std::ostream* os) {
    *os << c.scenario << ", " << c.mode << ", latency <= " << c.latency_us << " us";
}

class SpiFpgaLanding : public ::testing::TestWithParam<LandingCase> {};

TEST_P(SpiFpgaLanding, CountsEqualTheCommandAtEveryRestPoint) {
    const LandingCase c = GetParam();
    const auto out =
        run_spi(c.scenario, {std::string("planner.mode=\"") + c.mode + "\"",
                             "host.latency_max_us=" + std::to_string(c.latency_us), "mechanics.model=ideal"});
    ASSERT_TRUE(out.ok) << out.failure;
    const auto& in = out.arch.input;
    const bool exact_stop = std::string(c.mode) == "exact-stop";
    for (const auto& m : in.moves) {
        if (!exact_stop && &m != &in.moves.back()) continue;
        for (std::size_t a = 0; a < 2; ++a) {
            const double mm = a == 0 ? m.to_mm.x_mm : m.to_mm.y_mm;
            EXPECT_EQ(count_at(in.axes[a], m.t_end_ps), target_steps(mm, in.axes[a].steps_per_mm))
                << "move " << m.index << " axis " << a;
        }
    }
    if (exact_stop) {
        out.metrics.moves.for_each([](const auto& mm) { EXPECT_EQ(mm.steps_emitted, mm.steps_commanded) << mm.index; });
    }
    EXPECT_EQ(*out.metrics.path.job_end_um, 0.0);
    const auto& servo = out.report["spi-fpga"]["servo"];
    EXPECT_EQ(servo["rest_points_landed"], servo["rest_points"]);
    EXPECT_EQ(out.report["spi-fpga"]["fpga"]["fifo_drops"].get<int>(), 0);
}

INSTANTIATE_TEST_SUITE_P(
    Jobs, SpiFpgaLanding,
    ::testing::Values(LandingCase{"square_20mm", "exact-stop", 0}, LandingCase{"square_20mm", "exact-stop", 200},
                      LandingCase{"square_20mm", "continuous", 0}, LandingCase{"square_20mm", "continuous", 200},
                      LandingCase{"diagonal_45", "exact-stop", 0}, LandingCase{"diagonal_45", "exact-stop", 200},
                      LandingCase{"diagonal_45", "continuous", 0}, LandingCase{"diagonal_45", "continuous", 200},
                      LandingCase{"circle_r10", "exact-stop", 0}, LandingCase{"circle_r10", "exact-stop", 200},
                      LandingCase{"circle_r10", "continuous", 0}, LandingCase{"circle_r10", "continuous", 200},
                      LandingCase{"six_segment", "exact-stop", 0}, LandingCase{"six_segment", "exact-stop", 200},
                      LandingCase{"six_segment", "continuous", 0}, LandingCase{"six_segment", "continuous", 200}),
    [](const ::testing::TestParamInfo<LandingCase>& info) {
        std::string name = std::string(info.param.scenario) + "_" + info.param.mode + "_" +
                           std::to_string(info.param.latency_us) + "us";
        std::replace(name.begin(), name.end(), '-', '_');
        return name;
    });

// rate_apply = at-next-pulse: frames queue behind long STEP periods and the full FIFO drops them; the report warns,
// and the landing still ends on the target because it waits for an empty FIFO before trusting a count.
TEST(SpiFpgaAtNextPulse, FramesDropButTheJobStillEndsOnTheTarget) {
    const auto out = run_spi("square_at_next_pulse", {"mechanics.model=ideal"});
    ASSERT_TRUE(out.ok) << out.failure;
    EXPECT_GT(out.report["spi-fpga"]["fpga"]["fifo_drops"].get<int>(), 100);
    EXPECT_EQ(out.report["spi-fpga"]["fpga"]["fifo_max_level"].get<int>(), 4);
    ASSERT_FALSE(out.arch.warnings.empty());
    EXPECT_EQ(out.arch.warnings.front().kind, "fifo_drops");
    EXPECT_NE(out.arch.warnings.front().text.find("rate frames dropped by the full FIFO"), std::string::npos);
    EXPECT_EQ(*out.metrics.path.job_end_um, 0.0);
}

// The estimate holds every move to rest at both ends: the exact-stop square runs within it.
TEST(SpiFpgaEstimate, ExactStopSquareRunsWithinItsEstimate) {
    const auto out = run_spi("square_exact_stop");
    ASSERT_TRUE(out.ok) << out.failure;
    // Rapids of 14.14 mm at 1200 mm/min (20 mm/s) and sides of 20 mm at F800 (13.33 mm/s), each plus one
    // speed change from rest at half the 1000 mm/s^2 axis limit (trapezoidal): v / 500 mm/s^2.
    const double rapid_s = std::sqrt(200.0) / 20.0 + 20.0 / 500.0;
    const double side_s = 20.0 / (800.0 / 60.0) + (800.0 / 60.0) / 500.0;
    const double expected_s = 2 * rapid_s + 4 * side_s;
    EXPECT_NEAR(out.report.at("scenario").at("estimated_s").get<double>(), expected_s, 1e-9);
    EXPECT_LT(out.metrics.timing.job_time_s, expected_s);
}
