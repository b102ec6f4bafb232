// The carriage's sampling (tool_sampler.hpp) and the mechanics worker thread (mechanics_worker.hpp), with a fake
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

// X steps at 0.5 and 1.2 ms, Y at 1.2 ms too, periodic samples every 1 ms. The first step arms them at 1.5 ms;
// X is at rest from 3.7 ms, Y from 3.7 ms, so the samples at 1.5, 2.5 and 3.5 ms see motion and the one at 4.5 ms
// rest: the last. The steps at 1.2 ms give one sample.
TEST(ToolSampler, PeriodicSamplesFromTheFirstStepUntilBothAxesRest) {
    FakeAxis x;
    FakeAxis y;
    ToolSampler sampler(x, y, {10.0, 20.0}, kMs);
    sampler.on_start(0);
    x.on_microstep(kMs / 2, 3, 32);
    ASSERT_EQ(sampler.on_step(kMs / 2), std::optional<TimePs>(3 * kMs / 2));
    x.on_microstep(6 * kMs / 5, 4, 32);
    EXPECT_EQ(sampler.on_step(6 * kMs / 5), std::nullopt);  // already armed
    y.on_microstep(6 * kMs / 5, -2, 32);
    EXPECT_EQ(sampler.on_step(6 * kMs / 5), std::nullopt);
    std::optional<TimePs> next = 3 * kMs / 2;
    std::vector<TimePs> periodic;
    while (next) {
        periodic.push_back(*next);
        next = sampler.on_period(*next);
    }
    EXPECT_EQ(periodic, (std::vector<TimePs>{3 * kMs / 2, 5 * kMs / 2, 7 * kMs / 2, 9 * kMs / 2}));
    EXPECT_EQ(times(sampler.samples()),
              (std::vector<TimePs>{0, kMs / 2, 6 * kMs / 5, 3 * kMs / 2, 5 * kMs / 2, 7 * kMs / 2, 9 * kMs / 2}));
    EXPECT_DOUBLE_EQ(sampler.samples()[2].pos.x_mm, 14.0);  // the later step at 1.2 ms overwrote the first
    EXPECT_DOUBLE_EQ(sampler.samples()[2].pos.y_mm, 18.0);
    // A step after the rest arms them again, one period after it.
    x.on_microstep(6 * kMs, 5, 32);
    EXPECT_EQ(sampler.on_step(6 * kMs), std::optional<TimePs>(7 * kMs));
    EXPECT_EQ(times(sampler.take_before(5 * kMs / 2)), (std::vector<TimePs>{0, kMs / 2, 6 * kMs / 5, 3 * kMs / 2}));
    EXPECT_EQ(times(sampler.samples()), (std::vector<TimePs>{5 * kMs / 2, 7 * kMs / 2, 9 * kMs / 2, 6 * kMs}));
}

TEST(ToolSampler, WithoutAPeriodOnlyTheStartAndTheSteps) {
    FakeAxis x;
    FakeAxis y;
    ToolSampler sampler(x, y, {}, 0);
    sampler.on_start(0);
    EXPECT_EQ(sampler.on_step(kMs), std::nullopt);
    EXPECT_EQ(times(sampler.samples()), (std::vector<TimePs>{0, kMs}));
}

// The worker's run of the sequence of the first test: the same samples, the same calls on each axis in the same
// order, the periodic sample at 2.5 ms before a microstep at that instant (the kernel's order: a timed event
// before the STEP edge's delta cycles), and the rest then seen before it.
TEST(MechanicsWorker, MakesTheSynchronousCallsInTheirOrder) {
    FakeAxis x;
    FakeAxis y;
    ToolSampler sampler(x, y, {10.0, 20.0}, kMs);
    MechanicsWorker worker(x, y, sampler);
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
    EXPECT_EQ(end.last_periodic_ps, std::optional<TimePs>(7 * kMs / 2));
    EXPECT_TRUE(end.periodic_past_bound);  // Y moved at 2.5 ms: at rest only from 5.0 ms
    EXPECT_EQ(times(worker.samples_left()), (std::vector<TimePs>{6 * kMs / 5, 3 * kMs / 2, 5 * kMs / 2, 7 * kMs / 2}));
    EXPECT_DOUBLE_EQ(worker.samples_left()[2].pos.y_mm, 19.0);  // the step at 2.5 ms overwrote its periodic sample
    EXPECT_EQ(x.m_calls, (std::vector<TimePs>{-0, kMs / 2, -kMs / 2, 6 * kMs / 5, -6 * kMs / 5, -3 * kMs / 2,
                                               -5 * kMs / 2, -5 * kMs / 2, -7 * kMs / 2}));
    EXPECT_EQ(y.m_calls, (std::vector<TimePs>{-0, -kMs / 2, 6 * kMs / 5, -6 * kMs / 5, -3 * kMs / 2, -5 * kMs / 2,
                                               5 * kMs / 2, -5 * kMs / 2, -7 * kMs / 2}));
}

TEST(MechanicsWorker, TheBoundTakesThePeriodicSampleAtItWhenInclusive) {
    for (const bool inclusive : {false, true}) {
        FakeAxis x;
        FakeAxis y;
        ToolSampler sampler(x, y, {}, kMs);
        MechanicsWorker worker(x, y, sampler);
        worker.start(0);
        worker.microstep(0, 0, 1, 32);
        worker.step(0);
        const MechanicsWorker::End end = worker.finish(2 * kMs, inclusive);
        EXPECT_EQ(end.last_periodic_ps, std::optional<TimePs>(inclusive ? 2 * kMs : kMs));
        EXPECT_TRUE(end.periodic_past_bound);
    }
}

TEST(MechanicsWorker, AFaultOnTheWorkerReachesTheSimulation) {
    FakeAxis x;
    FakeAxis y;
    x.m_throw_at_ps = 2 * kMs;
    ToolSampler sampler(x, y, {}, kMs);
    MechanicsWorker worker(x, y, sampler);
    worker.start(0);
    worker.microstep(0, 2 * kMs, 1, 32);
    EXPECT_THROW((void)worker.take_before(3 * kMs), std::runtime_error);
    EXPECT_THROW((void)worker.finish(3 * kMs, true), std::runtime_error);
}

}  // namespace
}  // namespace cnc::mech
