// SystemC tests of the DRV8825, carriage and laser head (one TEST per process: ctest runs each separately).
#define SC_INCLUDE_DYNAMIC_PROCESSES
#include <gtest/gtest.h>

#include <systemc>
#include <vector>

#include "common/edge_log.hpp"
#include "mechanics/carriage.hpp"
#include "mechanics/core/ideal_stepper.hpp"
#include "mechanics/core/transmission.hpp"
#include "mechanics/drv8825.hpp"
#include "mechanics/laser_head.hpp"

using cnc::Edge;
using cnc::TimePs;
using namespace cnc::mech;

namespace {

constexpr TimePs kUs = cnc::kPsPerUs;

TimePs now_ps() {
    return static_cast<TimePs>(sc_core::sc_time_stamp().value());
}
sc_core::sc_time at(TimePs t) {
    return sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t));
}

// Plays time-ordered level changes onto a signal from its own thread, each `delta_cycles` delta cycles
// after its time stamp begins (to make writers of one instant act in different delta cycles).
void drive(sc_core::sc_signal<bool>& s, std::vector<Edge> edges, int delta_cycles = 0) {
    sc_core::sc_spawn([&s, edges, delta_cycles] {
        for (const Edge& e : edges) {
            sc_core::wait(at(e.t_ps - now_ps()));
            for (int d = 0; d < delta_cycles; ++d) sc_core::wait(sc_core::SC_ZERO_TIME);
            s.write(e.level);
        }
    });
}

// `n` STEP pulses, `high` wide, every `period`, the first rising at t0.
std::vector<Edge> pulses(TimePs t0, int n, TimePs period, TimePs high = 2 * kUs) {
    std::vector<Edge> e;
    for (int i = 0; i < n; ++i) {
        e.push_back({t0 + i * period, true});
        e.push_back({t0 + i * period + high, false});
    }
    return e;
}

// A DRV8825 with its pins on signals, MODE pins set for `microsteps`, enabled.
struct DriverBench {
    sc_core::sc_signal<bool> step, dir, n_enbl, m0, m1, m2;
    IdealStepper motor{1.8};
    Drv8825 drv;

    DriverBench(const char* name, const Drv8825Config& cfg, int microsteps = 32)
        : step((std::string(name) + "_step").c_str()),
          dir((std::string(name) + "_dir").c_str()),
          n_enbl((std::string(name) + "_n_enbl").c_str()),
          m0((std::string(name) + "_m0").c_str()),
          m1((std::string(name) + "_m1").c_str()),
          m2((std::string(name) + "_m2").c_str()),
          drv(name, cfg, motor) {
        drv.step(step);
        drv.dir(dir);
        drv.n_enbl(n_enbl);
        drv.m0(m0);
        drv.m1(m1);
        drv.m2(m2);
        set_mode(microsteps);
    }
    void set_mode(int microsteps) {
        const ModePins p = mode_pins_for(microsteps);
        m0.write(p.m0);
        m1.write(p.m1);
        m2.write(p.m2);
    }
};

}  // namespace

TEST(Drv8825Model, StepsWithDirLowCountDown) {
    DriverBench b("x", Drv8825Config{});
    drive(b.step, pulses(10 * kUs, 100, 312'500'000));
    sc_core::sc_start(at(40'000 * kUs));
    EXPECT_EQ(b.drv.stats().steps, 100);
    EXPECT_EQ(b.drv.position_microsteps(), -100);
    EXPECT_DOUBLE_EQ(b.drv.position_full_steps(), -3.125);
    EXPECT_DOUBLE_EQ(b.motor.shaft_angle_deg(now_ps()), -5.625);
    EXPECT_EQ(b.drv.timing().total_violations(), 0);
}

TEST(Drv8825Model, DirHighCountsUpAndPolarityIsConfigurable) {
    Drv8825Config inverted;
    inverted.dir_high_is_positive = false;
    DriverBench a("a", Drv8825Config{}, 8);
    DriverBench b("b", inverted, 8);
    a.dir.write(true);
    b.dir.write(true);
    drive(a.step, pulses(10 * kUs, 3, 100 * kUs));
    drive(b.step, pulses(10 * kUs, 3, 100 * kUs));
    sc_core::sc_start(at(1'000 * kUs));
    EXPECT_EQ(a.drv.position_microsteps(), 12);  // 3 eighth-steps = 12 / 32
    EXPECT_EQ(b.drv.position_microsteps(), -12);
}

TEST(Drv8825Model, StepsWhileDisabledAreNotCounted) {
    DriverBench b("x", Drv8825Config{});
    b.dir.write(true);
    drive(b.n_enbl, {{100 * kUs, true}, {2'000 * kUs, false}});
    drive(b.step, pulses(10 * kUs, 30, 100 * kUs));  // rises at 10, 110, ..., 2910 us
    sc_core::sc_start(at(4'000 * kUs));
    EXPECT_EQ(b.drv.stats().ignored_disabled, 19);  // 110 .. 1910 us
    EXPECT_EQ(b.drv.stats().steps, 11);
    EXPECT_EQ(b.drv.position_microsteps(), 11);
}

TEST(Drv8825Model, LateDirChangeIsASetupViolationAndTheSampledLevelWins) {
    DriverBench b("x", Drv8825Config{});
    // DIR rises 100 ns before the first STEP rise: the edge sees DIR high (a setup violation of 100 ns).
    // DIR falls at the very instant of the second rise: the edge sees the level before it, still high.
    drive(b.dir, {{100 * kUs - 100'000, true}, {200 * kUs, false}});
    drive(b.step, pulses(100 * kUs, 3, 100 * kUs));
    sc_core::sc_start(at(1'000 * kUs));
    EXPECT_EQ(b.drv.position_microsteps(), 1 + 1 - 1);
    const RuleStats& setup = b.drv.timing()[TimingRule::DirSetup];
    EXPECT_EQ(setup.violations, 2);
    EXPECT_EQ(setup.worst_ps, 0);
}

TEST(Drv8825Model, StrictModeDropsAShortPulse) {
    Drv8825Config strict;
    strict.strict = true;
    DriverBench s("s", strict);
    DriverBench l("l", Drv8825Config{});
    for (DriverBench* b : {&s, &l}) {
        b->dir.write(true);
        std::vector<Edge> e = pulses(10 * kUs, 2, 100 * kUs);
        for (const Edge& p : pulses(300 * kUs, 1, 0, 1 * kUs)) e.push_back(p);  // 1 us high
        drive(b->step, e);
    }
    sc_core::sc_start(at(1'000 * kUs));
    EXPECT_EQ(s.drv.stats().steps, 2);
    EXPECT_EQ(s.drv.stats().ignored_short, 1);
    EXPECT_EQ(s.drv.position_microsteps(), 2);
    EXPECT_EQ(l.drv.stats().steps, 3);  // default: every rise counts, the violation is only reported
    EXPECT_EQ(l.drv.position_microsteps(), 3);
    EXPECT_EQ(l.drv.timing()[TimingRule::StepHigh].violations, 1);
    EXPECT_EQ(l.drv.timing()[TimingRule::StepHigh].worst_ps, 1 * kUs);
}

TEST(Drv8825Model, ModeChangeMidRunGoesToTheNextValidState) {
    DriverBench b("x", Drv8825Config{});
    b.dir.write(true);
    drive(b.step, pulses(10 * kUs, 6, 100 * kUs));  // rises at 10 .. 510 us
    sc_core::sc_spawn([&b] {
        sc_core::wait(at(350 * kUs));  // after 4 steps at 1/32
        b.set_mode(1);
    });
    sc_core::sc_start(at(1'000 * kUs));
    EXPECT_EQ(b.drv.position_microsteps(), 64);  // 4 -> 32 (next full-step state) -> 64
    EXPECT_EQ(b.drv.stats().steps, 6);
}

TEST(CarriageModel, SimultaneousXYStepsMergeIntoOneSample) {
    DriverBench x("x", Drv8825Config{});
    DriverBench y("y", Drv8825Config{});
    const Belt belt(20, 2.0);  // 160 steps/mm at 1/32
    const RigidDrive drive_x(x.motor, belt);
    const RigidDrive drive_y(y.motor, belt);
    Carriage carriage("carriage",
                      CarriageConfig{{&x.drv.step_event(), &drive_x}, {&y.drv.step_event(), &drive_y}, {10.0, 20.0}});
    x.dir.write(true);
    drive(x.step, pulses(100 * kUs, 2, 100 * kUs));     // X at 100 and 200 us
    drive(y.step, pulses(100 * kUs, 1, 100 * kUs), 3);  // Y (DIR low) at 100 us only, 3 delta cycles later
    sc_core::sc_start(at(1'000 * kUs));

    const auto& s = carriage.samples();
    ASSERT_EQ(s.size(), 3U);
    EXPECT_EQ(s[0].t_ps, 0);
    EXPECT_DOUBLE_EQ(s[0].pos.x_mm, 10.0);
    EXPECT_DOUBLE_EQ(s[0].pos.y_mm, 20.0);
    EXPECT_EQ(s[1].t_ps, 100 * kUs);  // the diagonal step: one sample with both axes moved
    EXPECT_DOUBLE_EQ(s[1].pos.x_mm, 10.00625);
    EXPECT_DOUBLE_EQ(s[1].pos.y_mm, 19.99375);
    EXPECT_EQ(s[2].t_ps, 200 * kUs);
    EXPECT_DOUBLE_EQ(s[2].pos.x_mm, 10.0125);
    EXPECT_DOUBLE_EQ(s[2].pos.y_mm, 19.99375);
    EXPECT_DOUBLE_EQ(carriage.position().x_mm, 10.0125);
}

TEST(LaserHeadModel, FollowsThePinAndAddsUpOnTime) {
    sc_core::sc_signal<bool> laser("laser");
    LaserHead head("head");
    head.laser(laser);
    drive(laser, {{1'000 * kUs, true}, {3'000 * kUs, false}, {5'000 * kUs, true}});
    // On 1..3 ms and from 5 ms: 1 ms by 2 ms (on, still open), 2 ms by 4 ms (off), 3 ms by 6 ms (on again).
    sc_core::sc_start(at(2'000 * kUs));
    EXPECT_TRUE(head.is_on());
    EXPECT_EQ(head.on_time_ps(), 1'000 * kUs);
    sc_core::sc_start(at(2'000 * kUs));
    EXPECT_FALSE(head.is_on());
    EXPECT_EQ(head.on_time_ps(), 2'000 * kUs);
    sc_core::sc_start(at(2'000 * kUs));
    EXPECT_TRUE(head.is_on());
    EXPECT_EQ(head.on_time_ps(), 3'000 * kUs);
}
