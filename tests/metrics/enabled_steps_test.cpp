#include <gtest/gtest.h>

#include "metrics/enabled_steps.hpp"

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
    const EdgeLog late = enabled_steps(kStep, EdgeLog{"n_enbl_x", false, {{30, true}, {55, false}}},
                                       EnableLevel::ActiveLow);
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

}  // namespace
}  // namespace cnc::metrics
