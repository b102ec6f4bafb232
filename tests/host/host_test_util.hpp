// Helpers for the host core tests: run G-code text through the interpreter and check BadInput messages.
#pragma once
#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <sstream>
#include <string>

#include "common/bad_input.hpp"
#include "host/core/gcode.hpp"
#include "support/bad_input_message.hpp"

namespace cnc::host::test {

inline constexpr double kEps = 1e-9;

inline void expect_point(geom::Vec2 p, double x_mm, double y_mm) {
    EXPECT_NEAR(p.x_mm, x_mm, kEps);
    EXPECT_NEAR(p.y_mm, y_mm, kEps);
}

inline Program run_gcode(const std::string& text, const InterpreterOptions& opt = {}) {
    std::istringstream in(text);
    return interpret(in, "t.nc", opt);
}

using cnc::test::bad_input_message;

// Expects BadInput whose message contains every one of `parts`.
inline void expect_bad_input(const std::function<void()>& fn, std::initializer_list<std::string> parts) {
    const std::string msg = bad_input_message(fn);
    for (const std::string& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
}

inline void expect_gcode_error(const std::string& text, std::initializer_list<std::string> parts) {
    expect_bad_input([&] { run_gcode(text); }, parts);
}

}  // namespace cnc::host::test
