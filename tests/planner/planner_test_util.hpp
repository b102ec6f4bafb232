// Helpers for the planner tests: G-code text to a Program, dense sampling, distance to the programmed path.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

#include "common/bad_input.hpp"
#include "host/core/gcode.hpp"
#include "host/core/planner/planner.hpp"
#include "support/bad_input_message.hpp"

namespace cnc::host::planner::test {

// `rapid_feed_mm_per_min`: the machine's rapid speed, the path speed the planner gives G0 (capped by the axes).
inline Program gcode(const std::string& text, double rapid_feed_mm_per_min = 1200.0) {
    std::istringstream in(text);
    InterpreterOptions opt;
    opt.rapid_feed_mm_per_min = rapid_feed_mm_per_min;
    return interpret(in, "t.nc", opt);
}

// A rapid speed above every axis limit of the tests (100 mm/s): G0 runs as fast as the axes allow.
inline constexpr double kRapidAboveTheAxes_mm_per_min = 60'000.0;

inline PlannerConfig config(BlendMode mode, Profile profile = Profile::Trapezoidal) {
    PlannerConfig cfg;
    cfg.mode = mode;
    cfg.profile = profile;
    return cfg;
}

// Calls fn on samples every dt_s from 0 to the end (the end included).
inline void for_each_sample(const Trajectory& traj, double dt_s, const std::function<void(const Sample&)>& fn) {
    const double end = traj.duration_s();
    const long n = static_cast<long>(std::ceil(end / dt_s));
    for (long i = 0; i <= n; ++i) fn(traj.at(std::min(end, static_cast<double>(i) * dt_s)));
}

// Distance from p to the nearest programmed move (the contour error of a tool at p).
inline double contour_error(const Program& program, geom::Vec2 p) {
    double best = std::numeric_limits<double>::infinity();
    for (const ProgrammedMove& m : program.moves) best = std::min(best, m.path.distance_to(p));
    return best;
}

using cnc::test::bad_input_message;

}  // namespace cnc::host::planner::test
