// The carriage's sampling (tool_sampler.hpp) and the mechanics worker threads (mechanics_worker.hpp), with a fake
// axis whose position and rest are known at every time: the expected samples are worked out by hand below.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "common/units.hpp"
#include "mechanics/core/carriage_drive.hpp"
#include "mechanics/core/mechanics_worker.hpp"
#include "mechanics/core/motor.hpp"
#include "mechanics/core/tool_sampler.hpp"

namespace cnc::mech {
namespace {

constexpr TimePs kMs = kPsPerMs;

// Sits at 1 mm per microstep unit from its last microstep on, and is at rest from 2.5 ms after it (or from the
// start, before any); every query is logged, so that the call order can be checked too.
class FakeAxis : public StepperMotor, public CarriageDrive {
public:
    void on_microstep(TimePs t_ps, std::int64_t index, int) override {
        if (t_ps == m_throw_at_ps) throw std::runtime_error("fake axis: fault");
        m_units = index;
        m_last_ps = t_ps;
        m_calls.push_back(t_ps);
    }
    void on_enable(TimePs, bool) override {}
    [[nodiscard]] double shaft_angle_deg(TimePs) const override { return 0.0; }
    [[nodiscard]] double carriage_mm(TimePs t_ps) const override {
        m_now_ps = t_ps;
        m_calls.push_back(-t_ps);
        return static_cast<double>(m_units);
    }
    [[nodiscard]] bool at_rest() const override { return m_last_ps < 0 || m_now_ps - m_last_ps >= 5 * kMs / 2; }

    TimePs m_throw_at_ps = -1;
    mutable std::vector<TimePs> m_calls;  // microsteps at t, queries at -t

private:
    std::int64_t m_units = 0;
    TimePs m_last_ps = -1;
    mutable TimePs m_now_ps = 0;
};

std::vector<TimePs> times(const std::vector<ToolSample>& samples) {
    std::vector<TimePs> t;
    for (const ToolSample& s : samples) t.push_back(s.t_ps);
    return t;
}

// The start arms the periodic samples on the 1 ms grid; X steps at 0.5 and 1.2 ms, Y at 1.2 ms too. X is at rest
// from 3.7 ms, Y from 3.7 ms (2.5 ms after their last microsteps), so the samples at 1, 2 and 3 ms see motion and
// the one at 4 ms rest: the last. The steps at 1.2 ms give one sample.
TEST(ToolSampler, PeriodicSamplesOnTheGridFromTheStartUntilBothAxesRest) {
    FakeAxis x;
    FakeAxis y;
    ToolSampler sampler(x, y, {10.0, 20.0}, kMs);
    ASSERT_EQ(sampler.on_start(0), std::optional<TimePs>(kMs));
    x.on_microstep(kMs / 2, 3, 32);
    EXPECT_EQ(sampler.on_step(kMs / 2), std::nullopt);  // already armed
    ASSERT_EQ(sampler.on_period(kMs), std::optional<TimePs>(2 * kMs));
    x.on_microstep(6 * kMs / 5, 4, 32);
    EXPECT_EQ(sampler.on_step(6 * kMs / 5), std::nullopt);
    y.on_microstep(6 * kMs / 5, -2, 32);
    EXPECT_EQ(sampler.on_step(6 * kMs / 5), std::nullopt);
    std::optional<TimePs> next = 2 * kMs;
    std::vector<TimePs> periodic;
    while (next) {
        periodic.push_back(*next);
        next = sampler.on_period(*next);
    }
    EXPECT_EQ(periodic, (std::vector<TimePs>{2 * kMs, 3 * kMs, 4 * kMs}));
    EXPECT_EQ(times(sampler.samples()), (std::vector<TimePs>{0, kMs / 2, kMs, 6 * kMs / 5, 2 * kMs, 3 * kMs, 4 * kMs}));
    EXPECT_DOUBLE_EQ(sampler.samples()[3].pos.x_mm, 14.0);  // the later step at 1.2 ms overwrote the first
    EXPECT_DOUBLE_EQ(sampler.samples()[3].pos.y_mm, 18.0);
    // A step after the rest arms them again, at the next grid time; so does an enable change, without a sample.
    x.on_microstep(6 * kMs + kMs / 4, 5, 32);
    EXPECT_EQ(sampler.on_step(6 * kMs + kMs / 4), std::optional<TimePs>(7 * kMs));
    EXPECT_EQ(sampler.on_period(7 * kMs), std::optional<TimePs>(8 * kMs));
    EXPECT_EQ(sampler.on_period(8 * kMs), std::optional<TimePs>(9 * kMs));
    EXPECT_EQ(sampler.on_period(9 * kMs), std::nullopt);
    EXPECT_EQ(sampler.on_enable(10 * kMs), std::optional<TimePs>(11 * kMs));
    EXPECT_EQ(sampler.on_enable(21 * kMs / 2), std::nullopt);  // already armed
    EXPECT_EQ(times(sampler.take_before(2 * kMs)), (std::vector<TimePs>{0, kMs / 2, kMs, 6 * kMs / 5}));
    EXPECT_EQ(times(sampler.samples()),
              (std::vector<TimePs>{2 * kMs, 3 * kMs, 4 * kMs, 6 * kMs + kMs / 4, 7 * kMs, 8 * kMs, 9 * kMs}));
}

TEST(ToolSampler, WithoutAPeriodOnlyTheStartAndTheSteps) {
    FakeAxis x;
    FakeAxis y;
    ToolSampler sampler(x, y, {}, 0);
    EXPECT_EQ(sampler.on_start(0), std::nullopt);
    EXPECT_EQ(sampler.on_step(kMs), std::nullopt);
    EXPECT_EQ(sampler.on_enable(2 * kMs), std::nullopt);
    EXPECT_EQ(times(sampler.samples()), (std::vector<TimePs>{0, kMs}));
}

// The workers' run of a sequence like the first test's, Y stepping at 2.5 ms too: the samples the synchronous
// sampler takes of the same calls (run here on two other fake axes), and on each axis the calls worked out by
// hand: its microsteps, a reading at the start and every step of either axis, and one at each grid time at which
// it does not rest (Y is not read at 1 ms: it rests until its first microstep).
TEST(MechanicsWorker, ReadsEachAxisWhereTheSamplerWillWantIt) {
    FakeAxis x;
    FakeAxis y;
    MechanicsWorker worker({&x, &x}, {&y, &y}, {10.0, 20.0}, kMs);
    FakeAxis sync_x;
    FakeAxis sync_y;
    ToolSampler sampler(sync_x, sync_y, {10.0, 20.0}, kMs);

    worker.start(0);
    worker.microstep(0, kMs / 2, 3, 32);
    worker.step(kMs / 2);
    worker.microstep(0, 6 * kMs / 5, 4, 32);
    worker.microstep(1, 6 * kMs / 5, -2, 32);
    worker.step(6 * kMs / 5);
    EXPECT_EQ(times(worker.take_before(kMs)), (std::vector<TimePs>{0, kMs / 2}));
    worker.microstep(1, 5 * kMs / 2, -1, 32);
    worker.step(5 * kMs / 2);
    worker.mark(4 * kMs);
    const MechanicsWorker::End end = worker.finish(9 * kMs / 2, false);

    (void)sampler.on_start(0);
    sync_x.on_microstep(kMs / 2, 3, 32);
    (void)sampler.on_step(kMs / 2);
    (void)sampler.on_period(kMs);
    sync_x.on_microstep(6 * kMs / 5, 4, 32);
    sync_y.on_microstep(6 * kMs / 5, -2, 32);
    (void)sampler.on_step(6 * kMs / 5);
    (void)sampler.on_period(2 * kMs);
    sync_y.on_microstep(5 * kMs / 2, -1, 32);
    (void)sampler.on_step(5 * kMs / 2);
    (void)sampler.on_period(3 * kMs);
    EXPECT_EQ(sampler.on_period(4 * kMs), std::optional<TimePs>(5 * kMs));  // Y moves until 5.0 ms
    EXPECT_EQ(times(sampler.take_before(kMs)), (std::vector<TimePs>{0, kMs / 2}));

    EXPECT_EQ(end.last_periodic_ps, std::optional<TimePs>(4 * kMs));
    EXPECT_TRUE(end.periodic_past_bound);
    ASSERT_EQ(times(worker.samples_left()),
              (std::vector<TimePs>{kMs, 6 * kMs / 5, 2 * kMs, 5 * kMs / 2, 3 * kMs, 4 * kMs}));
    ASSERT_EQ(times(sampler.samples()), times(worker.samples_left()));
    for (std::size_t k = 0; k < sampler.samples().size(); ++k) {
        EXPECT_DOUBLE_EQ(worker.samples_left()[k].pos.x_mm, sampler.samples()[k].pos.x_mm);
        EXPECT_DOUBLE_EQ(worker.samples_left()[k].pos.y_mm, sampler.samples()[k].pos.y_mm);
    }
    EXPECT_DOUBLE_EQ(worker.samples_left()[3].pos.y_mm, 19.0);  // Y's step at 2.5 ms
    EXPECT_EQ(x.m_calls, (std::vector<TimePs>{-0, kMs / 2, -kMs / 2, -kMs, 6 * kMs / 5, -6 * kMs / 5, -2 * kMs,
                                              -5 * kMs / 2, -3 * kMs, -4 * kMs}));
    EXPECT_EQ(y.m_calls, (std::vector<TimePs>{-0, -kMs / 2, 6 * kMs / 5, -6 * kMs / 5, -2 * kMs, 5 * kMs / 2,
                                              -5 * kMs / 2, -3 * kMs, -4 * kMs}));
}

TEST(MechanicsWorker, TheBoundTakesThePeriodicSampleAtItWhenInclusive) {
    for (const bool inclusive : {false, true}) {
        FakeAxis x;
        FakeAxis y;
        MechanicsWorker worker({&x, &x}, {&y, &y}, {}, kMs);
        worker.start(0);
        worker.microstep(0, 0, 1, 32);
        worker.step(0);
        const MechanicsWorker::End end = worker.finish(2 * kMs, inclusive);
        EXPECT_EQ(end.last_periodic_ps, std::optional<TimePs>(inclusive ? 2 * kMs : kMs));
        EXPECT_TRUE(end.periodic_past_bound);
    }
}

// The metrics ask, without waiting, how far the samples are ready: never past the last mark, and past it once
// both workers have got there.
TEST(MechanicsWorker, SaysHowFarTheSamplesAreReady) {
    FakeAxis x;
    FakeAxis y;
    MechanicsWorker worker({&x, &x}, {&y, &y}, {}, kMs);
    worker.start(0);
    worker.microstep(0, kMs, 1, 32);
    worker.step(kMs);
    EXPECT_LE(worker.ready_ps(2 * kMs), 2 * kMs);
    EXPECT_EQ(times(worker.take_before(2 * kMs)), (std::vector<TimePs>{0, kMs}));
    EXPECT_EQ(worker.ready_ps(2 * kMs), 2 * kMs);
    (void)worker.finish(3 * kMs, true);
}

TEST(MechanicsWorker, AFaultOnAWorkerReachesTheSimulation) {
    FakeAxis x;
    FakeAxis y;
    x.m_throw_at_ps = 2 * kMs;
    MechanicsWorker worker({&x, &x}, {&y, &y}, {}, kMs);
    worker.start(0);
    worker.microstep(0, 2 * kMs, 1, 32);
    EXPECT_THROW((void)worker.take_before(3 * kMs), std::runtime_error);
    EXPECT_THROW((void)worker.finish(3 * kMs, true), std::runtime_error);
}

}  // namespace
}  // namespace cnc::mech
