#include <gtest/gtest.h>

#include "metrics/pulse/enabled_steps.hpp"

namespace cnc::metrics {
namespace {

const EdgeLog kStep{"step_x", false, {{10, true}, {20, false}, {30, true}, {40, false}, {50, true}, {60, false}}};

TEST(EnabledSteps, KeepsPulsesThatRiseWhileAnActiveLowEnableIsLow) {
    const EdgeLog n_enbl{"n_enbl_x", true, {{25, false}, {45, true}}};  // enabled 25..45
    const EdgeLog out = enabled_steps(kStep, n_enbl, EnableLevel::ActiveLow);
    EXPECT_EQ(out.name, "step_x");
    EXPECT_EQ(out.rising(), (std::vector<TimePs>{30}));
    EXPECT_EQ(out.falling(), (std::vector<TimePs>{40}));
    // a pulse that rises enabled keeps its fall after EN rises; an edge at an EN change sees the level before
    const EdgeLog late =
        enabled_steps(kStep, EdgeLog{"n_enbl_x", false, {{30, true}, {55, false}}}, EnableLevel::ActiveLow);
    EXPECT_EQ(late.rising(), (std::vector<TimePs>{10, 30}));
    EXPECT_EQ(late.falling(), (std::vector<TimePs>{20, 40}));
}

TEST(EnabledSteps, ActiveHighEnableIsTheMirror) {
    const EdgeLog enable{"en_x", false, {{25, true}, {45, false}}};  // enabled 25..45
    const EdgeLog out = enabled_steps(kStep, enable, EnableLevel::ActiveHigh);
    EXPECT_EQ(out.rising(), (std::vector<TimePs>{30}));
    EXPECT_EQ(out.falling(), (std::vector<TimePs>{40}));
    EXPECT_EQ(enabled_steps(kStep, enable, EnableLevel::ActiveLow).rising(), (std::vector<TimePs>{10, 50}));
}

// Read in pieces cut anywhere (inside a pulse, at an enable change, with enable edges after a piece's last STEP
// edge), the fold gives the whole run's pulses.
TEST(EnabledSteps, FoldedPieceByPieceEqualsTheWholeRun) {
    const EdgeLog n_enbl{"n_enbl_x", false, {{30, true}, {55, false}}};  // the second case above
    const EdgeLog whole = enabled_steps(kStep, n_enbl, EnableLevel::ActiveLow);
    for (TimePs cut = 0; cut <= 70; ++cut) {
        EdgeLog step = kStep;
        EdgeLog enable = n_enbl;
        EnabledStepsFold fold(enable.initial, EnableLevel::ActiveLow);
        EdgeLog got = fold.add(step.take_before(cut), enable.take_before(cut));
        const EdgeLog rest = fold.add(step.take_before(100), enable.take_before(100));
        got.edges.insert(got.edges.end(), rest.edges.begin(), rest.edges.end());
        EXPECT_EQ(got.rising(), whole.rising()) << "cut at " << cut;
        EXPECT_EQ(got.falling(), whole.falling()) << "cut at " << cut;
    }
}

}  // namespace
}  // namespace cnc::metrics
