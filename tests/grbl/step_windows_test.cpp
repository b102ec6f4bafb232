// The grbl architecture's move windows read from the STEP and DIR pins: a move ends at the pulse that brings both
// axes' counts to its end point, the next starts at the pulse after; DIR as the architecture reads it.
#include <gtest/gtest.h>

#include "architectures/grbl/step_windows.hpp"

namespace cnc::sim {
namespace {

EdgeLog pulses(const char* name, std::initializer_list<TimePs> rises) {
    EdgeLog log{name, false, {}};
    for (const TimePs t : rises) {
        log.add(t, true);
        log.add(t + 10, false);
    }
    return log;
}

// Two moves on grbl's DIR sense (high: negative): +2 X then (-1 X, +1 Y) with DIR X set high between them.
TEST(StepWindowFold, AMoveEndsAtThePulseThatReachesItsEnd) {
    StepWindowFold fold({{2, 0}, {1, 1}}, false);
    EdgeLog dir_x{"dir_x", false, {{250, true}}};
    const EdgeLog dir_y{"dir_y", false, {}};
    fold.add(pulses("step_x", {100, 200, 300}), dir_x, pulses("step_y", {300}), dir_y);
    ASSERT_EQ(fold.windows().size(), 2U);
    EXPECT_EQ(fold.windows()[0].t_begin_ps, 100);
    EXPECT_EQ(fold.windows()[0].t_end_ps, 200);
    EXPECT_EQ(fold.windows()[1].t_begin_ps, 300);
    EXPECT_EQ(fold.windows()[1].t_end_ps, 300);
    EXPECT_EQ(fold.steps_after_last(), 0);
}

// The edges come slice by slice; a move under way when the run stops is closed there, incomplete; pulses after the
// last move are counted, not windowed.
TEST(StepWindowFold, SlicesAndTheRunsEnd) {
    StepWindowFold fold({{0, 3}}, true);
    const EdgeLog low_x{"dir_x", false, {}};
    EdgeLog high_y{"dir_y", true, {}};
    fold.add(pulses("step_x", {}), low_x, pulses("step_y", {10, 20}), high_y);
    EXPECT_EQ(fold.windows().size(), 0U);
    fold.finish(500);
    ASSERT_EQ(fold.windows().size(), 1U);
    EXPECT_FALSE(fold.windows()[0].complete);
    EXPECT_EQ(fold.windows()[0].t_end_ps, 500);

    StepWindowFold over({{0, 1}}, true);
    over.add(pulses("step_x", {}), low_x, pulses("step_y", {10, 20, 30}), high_y);
    EXPECT_EQ(over.windows().size(), 1U);
    EXPECT_EQ(over.steps_after_last(), 2);
    const std::array<std::int64_t, 2> at{0, 3};
    EXPECT_EQ(over.position(), at);
}

}  // namespace
}  // namespace cnc::sim
