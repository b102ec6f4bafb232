#include <cmath>
#include <limits>

#include "planner_test_util.hpp"

namespace cnc::host::planner {
namespace {

using test::bad_input_message;

void expect_rejected(const PlannerConfig& cfg, const std::string& field) {
    const std::string msg = bad_input_message([&] { validate(cfg, "s.toml: planner"); });
    EXPECT_NE(msg.find("s.toml: planner"), std::string::npos) << msg;
    EXPECT_NE(msg.find(field), std::string::npos) << msg;
}

TEST(PlannerConfig, DefaultsAreValid) {
    EXPECT_NO_THROW(validate(PlannerConfig{}, "p"));
}

TEST(PlannerConfig, ZeroAccelerationNamesTheField) {
    PlannerConfig cfg;
    cfg.x.max_accel_mm_per_s2 = 0.0;
    expect_rejected(cfg, "x.max_accel_mm_per_s2");
}

TEST(PlannerConfig, EveryLimitMustBePositiveAndFinite) {
    const double bad[] = {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()};
    for (double v : bad) {
        PlannerConfig a;
        a.y.max_velocity_mm_per_s = v;
        expect_rejected(a, "y.max_velocity_mm_per_s");
        PlannerConfig b;
        b.x.max_jerk_mm_per_s3 = v;
        expect_rejected(b, "x.max_jerk_mm_per_s3");
        PlannerConfig c;
        c.y.max_accel_mm_per_s2 = v;
        expect_rejected(c, "y.max_accel_mm_per_s2");
    }
}

TEST(PlannerConfig, ToleranceAndLookahead) {
    PlannerConfig tol;
    tol.path_tolerance_mm = -0.01;
    expect_rejected(tol, "path_tolerance_mm");
    PlannerConfig zero_tol;
    zero_tol.path_tolerance_mm = 0.0;
    EXPECT_NO_THROW(validate(zero_tol, "p"));
    PlannerConfig look;
    look.lookahead_moves = 0;
    expect_rejected(look, "lookahead_moves");
}

TEST(PlannerConfig, PlanValidatesFirst) {
    PlannerConfig cfg;
    cfg.y.max_accel_mm_per_s2 = -3.0;
    const std::string msg = bad_input_message([&] { plan(test::gcode("G1 X1 F100\n"), cfg); });
    EXPECT_NE(msg.find("planner: y.max_accel_mm_per_s2"), std::string::npos) << msg;
}

}  // namespace
}  // namespace cnc::host::planner
