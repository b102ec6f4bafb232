// The servo thread's period logic (models/host/servo/core/servo_core.hpp) against an ideal stand-in for the FPGA:
// trajectory clock, rest points, one-period-late feedback, landing exactly on the targets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "host/core/gcode.hpp"
#include "host/core/planner/planner.hpp"
#include "host/servo/core/rate_word.hpp"
#include "host/servo/core/servo_core.hpp"
#include "host/servo/core/trajectory_clock.hpp"
#include "support/fed_job.hpp"

using cnc::kPsPerMs;
using cnc::kPsPerUs;
using cnc::TimePs;
using namespace cnc::host;
using namespace cnc::host::servo;

TEST(TrajectoryClock, LinearBetweenKnotsHeldInHoldsDepartsAtTheHoldsEnd) {
    TrajectoryClock c;
    c.add(0, 0.0);
    c.add(kPsPerMs, 1e-3);
    c.add(2 * kPsPerMs, 1.5e-3);  // clamped at a rest point
    c.add(3 * kPsPerMs, 1.5e-3);  // hold
    c.add(4 * kPsPerMs, 2.5e-3);
    EXPECT_DOUBLE_EQ(c.tau_at(500 * kPsPerUs), 0.5e-3);
    EXPECT_DOUBLE_EQ(c.tau_at(2500 * kPsPerUs), 1.5e-3);
    EXPECT_DOUBLE_EQ(c.tau_at(9 * kPsPerMs), 2.5e-3);
    EXPECT_DOUBLE_EQ(c.rate_at(500 * kPsPerUs), 1.0);
    EXPECT_DOUBLE_EQ(c.rate_at(1500 * kPsPerUs), 0.5);
    EXPECT_DOUBLE_EQ(c.rate_at(2500 * kPsPerUs), 0.0);
    EXPECT_EQ(c.depart_time(0.75e-3), 750 * kPsPerUs);
    EXPECT_EQ(c.depart_time(1.5e-3), 3 * kPsPerMs);
    EXPECT_EQ(c.depart_time(2.0e-3), 3500 * kPsPerUs);
    EXPECT_EQ(c.depart_time(5.0e-3), 4 * kPsPerMs);
    EXPECT_THROW(c.add(5 * kPsPerMs, 1e-3), std::logic_error);
}

// Dropping the knots behind a reader must leave what it still reads as the whole clock reads it (exact doubles,
// exact times), both when the time bound and when the tau bound decides, and a hold at the cut.
TEST(TrajectoryClock, DroppedKnotsLeaveTheReadingsFromTheCutOnAsTheyWere) {
    TrajectoryClock whole;
    TrajectoryClock cut;
    for (TrajectoryClock* c : {&whole, &cut}) {
        c->add(kPsPerMs, 0.0);  // the first knot at 1 ms: t_begin must stay there
        c->add(2 * kPsPerMs, 1e-3);
        c->add(3 * kPsPerMs, 1.5e-3);  // clamped at a rest point
        c->add(4 * kPsPerMs, 1.5e-3);  // hold
        c->add(5 * kPsPerMs, 1.5e-3);  // hold
        c->add(6 * kPsPerMs, 2.5e-3);
        c->add(7 * kPsPerMs, 3.5e-3);
    }
    // The tau bound decides: knots up to 4.5 ms are before t, but only those with tau <= 1.5e-3 may go (the last
    // kept is the hold's last knot, at 5 ms).
    cut.drop_before(6500 * kPsPerUs, 1.6e-3);
    EXPECT_EQ(cut.size(), 3U);
    EXPECT_EQ(cut.t_begin_ps(), kPsPerMs);
    EXPECT_EQ(cut.depart_time(1.5e-3), whole.depart_time(1.5e-3));  // the hold's end: 5 ms
    EXPECT_EQ(cut.depart_time(1.5e-3), 5 * kPsPerMs);
    for (const double tau : {1.6e-3, 2.0e-3, 2.5e-3, 3.1e-3, 9.0e-3}) {
        EXPECT_EQ(cut.depart_time(tau), whole.depart_time(tau)) << tau;
    }
    // The time bound decides: the last knot at or before 6.2 ms is the one at 6 ms.
    cut.drop_before(6200 * kPsPerUs, 9.0);
    EXPECT_EQ(cut.size(), 2U);
    for (const TimePs t : {6200 * kPsPerUs, 6500 * kPsPerUs, 7 * kPsPerMs, 8 * kPsPerMs}) {
        EXPECT_EQ(cut.at(t).tau_s, whole.at(t).tau_s) << t;
        EXPECT_EQ(cut.at(t).rate, whole.at(t).rate) << t;
    }
    // The last knot always stays: the clock goes on from it.
    cut.drop_before(9 * kPsPerMs, 9.0);
    EXPECT_EQ(cut.size(), 1U);
    EXPECT_EQ(cut.t_end_ps(), 7 * kPsPerMs);
    cut.add(8 * kPsPerMs, 4.5e-3);
    whole.add(8 * kPsPerMs, 4.5e-3);
    EXPECT_EQ(cut.at(7500 * kPsPerUs).tau_s, whole.at(7500 * kPsPerUs).tau_s);
}

namespace {

Program program(const std::string& text) {
    std::istringstream in(text);
    return interpret(in, "test.nc", InterpreterOptions{});
}

// What the servo knows of `text` before it starts, from a read of its own (as the spi-fpga run reads the job ahead).
ServoJob job_ahead(const std::string& text, const planner::PlannerConfig& pc) {
    cnc::test::FedJob ahead(text, pc);
    return {laser_intent(program(text)), count_rest_points(ahead.plan)};
}

// The rest points one after the other as a servo finds them: searched up to a horizon that runs on by 1 ms (a
// period) at a time, the pieces behind it dropped, until the last.
std::vector<double> rest_points_found(const std::string& text, const planner::PlannerConfig& pc) {
    cnc::test::FedJob fed(text, pc);
    std::vector<double> out;
    std::optional<double> after;
    for (double until = 0.0; until < 100.0; until += 1e-3) {
        while (const std::optional<double> r = next_rest_point(fed.plan, after, until)) {
            out.push_back(*r);
            after = r;
        }
        if (!out.empty() && last_rest_point(fed.plan, out.back())) break;
        fed.plan.drop_before(until);
    }
    return out;
}

ServoConfig config() {
    ServoConfig c;
    for (AxisServoConfig& a : c.axes) a = {160.0, 100.0, 1000.0};
    return c;
}

// Stand-in for the FPGA and the link: a word governs the whole next period; a generator keeps its phase while
// running, steps at once when a word starts it (as the seed's pulsegen, whose counter starts with the output
// high) and stops dead on a stop word. The host sees the count at the end of the previous period. `gain` scales
// the rate the generator really runs at (1 = exact).
struct IdealPlant {
    explicit IdealPlant(double gain = 1.0) : m_gain(gain) {}
    std::optional<cnc::spi::Feedback> feedback() const {
        if (!m_started) return std::nullopt;
        return cnc::spi::Feedback{{}, {static_cast<std::int32_t>(m_count[0]), static_cast<std::int32_t>(m_count[1])}};
    }
    void run(const PeriodRecord& rec, double period_s) {
        m_started = true;
        for (std::size_t a = 0; a < kAxes; ++a) {
            const double rate = signed_rate(rec.axes[a].word, 50'000'000) * m_gain;
            const bool was_running = m_running[a];
            m_running[a] = rate != 0.0;
            if (rate == 0.0) {
                m_phase[a] = 0.0;
                continue;
            }
            if (!was_running) m_phase[a] = rate > 0.0 ? 1.0 : -1.0;
            m_phase[a] += rate * period_s;
            const double whole = std::trunc(m_phase[a]);
            m_count[a] += static_cast<std::int64_t>(whole);
            m_phase[a] -= whole;
        }
    }
    std::array<std::int64_t, kAxes> m_count{};
    std::array<double, kAxes> m_phase{};
    std::array<bool, kAxes> m_running{};
    bool m_started = false;
    double m_gain;
};

// Runs the core to completion (or a period limit); returns the number of periods.
std::size_t run(ServoCore& core, IdealPlant& plant, std::size_t limit = 100'000) {
    std::size_t n = 0;
    while (!core.done() && n < limit) {
        const PeriodRecord& rec = core.step(plant.feedback());
        plant.run(rec, 1e-3);
        ++n;
    }
    return n;
}

}  // namespace

// The rest points found as the plan is read equal the whole plan's stops (its move windows' ends where the plan
// stops there: every move in exact stop, a reversal and a host wait in continuous mode) and its end, and the count
// read ahead of a run is theirs.
TEST(RestPoints, EveryStopOfThePlanAndItsEndFoundAsThePlanIsRead) {
    planner::PlannerConfig pc;
    pc.mode = planner::BlendMode::ExactStop;
    const std::string square = "G1 X10 F1200\nG1 X10 Y10\nG1 X0 Y10\n";
    const planner::Trajectory t = planner::plan(program(square), pc);
    const std::vector<double> r = rest_points_found(square, pc);
    ASSERT_EQ(r.size(), 3U);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(r[i], t.move_windows()[i].second);
    EXPECT_EQ(job_ahead(square, pc).rest_points, 3U);

    pc.mode = planner::BlendMode::Continuous;
    const std::string reversal = "G1 X10 F1200\nG1 X20\nG1 X10\n";  // colinear: no stop; reversal: stop; end
    const planner::Trajectory c = planner::plan(program(reversal), pc);
    EXPECT_EQ(rest_points_found(reversal, pc), (std::vector<double>{c.move_windows()[1].second, c.duration_s()}));
    EXPECT_EQ(job_ahead(reversal, pc).rest_points, 2U);

    // A dwell between two moves is a stop; one after the last move makes the plan's end a rest point of its own.
    const std::string dwells = "G1 X10 F1200\nG4 P0.5\nG1 X20\nG4 P0.25\n";
    const planner::Trajectory d = planner::plan(program(dwells), pc);
    EXPECT_EQ(rest_points_found(dwells, pc),
              (std::vector<double>{d.move_windows()[0].second, d.move_windows()[1].second, d.duration_s()}));
    EXPECT_EQ(d.duration_s(), d.move_windows()[1].second + 0.25);
    EXPECT_EQ(job_ahead(dwells, pc).rest_points, 3U);

    EXPECT_EQ(rest_points_found("", pc), std::vector<double>{0.0});
    EXPECT_EQ(job_ahead("", pc).rest_points, 1U);
}

TEST(ServoCore, FollowsOnePeriodBehindAndLandsExactlyAtEveryRestPoint) {
    planner::PlannerConfig pc;
    pc.mode = planner::BlendMode::ExactStop;
    const std::string text = "G1 X10.003 Y-2 F1200\nG1 X0 Y5.0031\n";
    cnc::test::FedJob fed(text, pc);
    ServoCore core(config(), fed.plan, job_ahead(text, pc));
    IdealPlant plant;
    // Each rest point held and its landing target, as the core heads for them.
    std::vector<std::pair<double, std::array<std::int64_t, 2>>> rests;
    while (!core.done()) {
        plant.run(core.step(plant.feedback()), 1e-3);
        if (core.rest_point_s() && (rests.empty() || rests.back().first != *core.rest_point_s())) {
            rests.emplace_back(*core.rest_point_s(), core.target());
        }
    }
    EXPECT_EQ(core.stats().rest_points, 2U);
    EXPECT_EQ(core.stats().rest_points_landed, 2U);
    // targets: round(10.003 x 160) = 1600 (1600.48), -320; 0, round(5.0031 x 160) = 800 (800.496)
    ASSERT_EQ(rests.size(), 2U);
    EXPECT_EQ(rests[0].second, (std::array<std::int64_t, 2>{1600, -320}));
    EXPECT_EQ(rests[1].second, (std::array<std::int64_t, 2>{0, 800}));
    EXPECT_EQ(plant.m_count, (std::array<std::int64_t, 2>{0, 800}));
    // The hold: tau stays at the first rest point until the first record that tracks again.
    const std::vector<PeriodRecord>& log = core.log();
    const double r0 = rests[0].first;
    std::size_t first_land = 0;
    while (log[first_land].mode != PeriodMode::Land) ++first_land;
    EXPECT_DOUBLE_EQ(log[first_land - 1].tau_s, r0);  // the period that reached it still tracked
    std::size_t release = first_land;
    while (log[release].mode == PeriodMode::Land) {
        EXPECT_DOUBLE_EQ(log[release].tau_s, r0);
        EXPECT_EQ(log[release].path_speed_mm_per_s, 0.0);
        ++release;
    }
    EXPECT_EQ(log[release].mode, PeriodMode::Track);
    EXPECT_DOUBLE_EQ(log[release].tau_s, r0 + 1e-3);
    // The count that released the hold was the target.
    EXPECT_EQ(log[release].axes[0].count, 1600);
    EXPECT_EQ(log[release].axes[1].count, -320);
    EXPECT_EQ(log.back().mode, PeriodMode::Done);
    // The clock has one knot per period at n ms.
    EXPECT_EQ(core.clock().size(), log.size());
    EXPECT_EQ(core.clock().t_end_ps(), static_cast<TimePs>(log.size() - 1) * kPsPerMs);
}

TEST(ServoCore, LandingPulsesAreSingleAndSeparatedByTwoStops) {
    // A generator running 3 % slow leaves the axes short at every stop: landing pulses make up the difference.
    planner::PlannerConfig pc;
    pc.mode = planner::BlendMode::ExactStop;
    const std::string text = "G1 X20 Y10 F3000\n";
    cnc::test::FedJob fed(text, pc);
    ServoCore core(config(), fed.plan, job_ahead(text, pc));
    IdealPlant plant(0.97);
    run(core, plant);
    ASSERT_TRUE(core.done());
    EXPECT_EQ(plant.m_count, (std::array<std::int64_t, 2>{3200, 1600}));
    EXPECT_GT(core.stats().landing_pulses, 0U);
    const std::vector<PeriodRecord>& log = core.log();
    const std::uint32_t land_period = landing_period_cycles(core.config());
    EXPECT_EQ(land_period, 100'000U);  // 2 ms at 50 MHz
    for (std::size_t i = 0; i < log.size(); ++i) {
        if (log[i].mode != PeriodMode::Land) continue;
        for (std::size_t a = 0; a < kAxes; ++a) {
            const cnc::spi::AxisRate& w = log[i].axes[a].word;
            if (w.period_cycles == 0) continue;
            EXPECT_EQ(w.period_cycles, land_period);
            ASSERT_LT(i + 2, log.size());
            EXPECT_EQ(log[i + 1].axes[a].word.period_cycles, 0U) << "period " << i;
            EXPECT_EQ(log[i + 2].axes[a].word.period_cycles, 0U) << "period " << i;
        }
    }
}

TEST(ServoCore, AStandingAxisCorrectsAnyErrorPastHalfAStep) {
    // Y must stay at 0 while X moves; a plant that once loses... here: Y starts 1 step off (count -1 injected).
    planner::PlannerConfig pc;
    const std::string text = "G1 X20 F600\n";
    cnc::test::FedJob fed(text, pc);
    ServoCore core(config(), fed.plan, job_ahead(text, pc));
    IdealPlant plant;
    plant.m_count[1] = -1;
    std::size_t n = 0;
    std::optional<std::size_t> fixed;
    while (!core.done() && n < 100'000) {
        const PeriodRecord& rec = core.step(plant.feedback());
        plant.run(rec, 1e-3);
        if (!fixed && plant.m_count[1] == 0) fixed = n;
        ++n;
    }
    ASSERT_TRUE(fixed.has_value());
    EXPECT_LE(*fixed, 10U);  // long before the move's end (2 s): not left to landing
    EXPECT_EQ(plant.m_count, (std::array<std::int64_t, 2>{3200, 0}));
}

TEST(ServoCore, LaserBitCoversTheCutsStretchOfPlanOnlyAndIsOffWhileLanding) {
    // Exact stop; the cut X0->10 at F600 takes 10 / 10 + 10 / 1000 = 1.01 s, the Y move under M5 the same.
    planner::PlannerConfig pc;
    pc.mode = planner::BlendMode::ExactStop;
    const std::string text = "M3 S1000\nG1 X10 F600\nM5\nG1 Y10\n";
    cnc::test::FedJob fed(text, pc);
    ServoCore core(config(), fed.plan, job_ahead(text, pc));
    IdealPlant plant;
    run(core, plant);
    ASSERT_TRUE(core.done());
    const std::vector<PeriodRecord>& log = core.log();
    std::vector<std::size_t> on;
    for (std::size_t n = 0; n < log.size(); ++n) {
        if (!log[n].laser_on) continue;
        on.push_back(n);
        EXPECT_EQ(log[n].mode, PeriodMode::Track) << n;
    }
    ASSERT_FALSE(on.empty());
    EXPECT_EQ(on.front(), 1U);                         // period 0 holds tau at 0 (nothing to carry yet)
    EXPECT_EQ(on.back() - on.front() + 1, on.size());  // one stretch
    // 1.01 s / 1 ms = 1010 periods; the clock adds 1 ms per period in floating point and can reach the rest
    // point with one more, vanishing step.
    EXPECT_GE(on.size(), 1010U);
    EXPECT_LE(on.size(), 1011U);
    EXPECT_DOUBLE_EQ(log[on.back()].tau_s - log[on.front() - 1].tau_s, 1.01);
    EXPECT_EQ(log[on.back() + 1].mode, PeriodMode::Land);
}

TEST(ServoCore, DroppedRecordsLeaveTheOthersAndThePeriodNumbersAsTheyWere) {
    // The same job twice, one log kept whole, the other dropped every 7 periods up to 3 behind: the records left
    // are the whole log's last ones, and the period numbers go on counting the dropped ones.
    const std::string text = "G1 X10 Y-2 F1200\nG1 X0 Y5\n";
    const planner::PlannerConfig pc;
    cnc::test::FedJob fed(text, pc);
    ServoCore whole(config(), fed.plan, job_ahead(text, pc));
    IdealPlant whole_plant;
    const std::size_t periods = run(whole, whole_plant);
    cnc::test::FedJob fed_again(text, pc);
    ServoCore dropped(config(), fed_again.plan, job_ahead(text, pc));
    IdealPlant plant;
    for (std::size_t n = 0; !dropped.done(); ++n) {
        plant.run(dropped.step(plant.feedback()), 1e-3);
        if (n % 7 == 6) dropped.drop_log_before(n - 2);
    }
    ASSERT_EQ(dropped.periods(), periods);
    ASSERT_GT(dropped.log_first(), 0U);
    EXPECT_EQ(dropped.log().size(), periods - dropped.log_first());
    EXPECT_LE(dropped.log().size(), 9U);  // at most 3 behind + 6 since the last drop
    for (std::uint64_t n = dropped.log_first(); n < periods; ++n) {
        EXPECT_EQ(dropped.record(n).n, static_cast<std::int64_t>(n));
        EXPECT_EQ(dropped.record(n).tau_s, whole.log()[n].tau_s);
        EXPECT_EQ(dropped.record(n).axes[0].word, whole.log()[n].axes[0].word);
    }
    dropped.drop_log_before(periods + 5);  // past the end: drops what there is
    EXPECT_EQ(dropped.periods(), periods);
    EXPECT_TRUE(dropped.log().empty());
}
