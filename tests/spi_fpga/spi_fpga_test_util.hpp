// Runs a shipped spi-fpga scenario in this test process (one SystemC elaboration per process), and helpers over
// its edge logs and report.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/shipped_run.hpp"

namespace cnc::test {

inline constexpr TimePs kClockPs = 20'000;  // 50 MHz FPGA clock

// With every edge and tool sample kept: the tests read them.
inline sim::RunOutcome run_spi(const std::string& name, const std::vector<std::string>& sets = {}) {
    return run_on_exact_clock("spi-fpga", name, sets, true);
}

// Net step count of an axis from its edge logs, over the rising edges at or before t_ps.
inline std::int64_t count_at(const metrics::AxisTrace& a, TimePs t_ps) {
    std::int64_t n = 0;
    for (const TimePs t : a.step.rising()) {
        if (t > t_ps) break;
        n += a.dir.level_at(t) == a.dir_high_is_positive ? 1 : -1;
    }
    return n;
}

// The step the host lands an axis on for a machine position (origin 0, 160 steps/mm).
inline std::int64_t target_steps(double mm, double steps_per_mm) {
    return std::llround(mm * steps_per_mm);
}

// A JSON number in ps (report times are in s).
inline TimePs ps_of(double seconds) {
    return static_cast<TimePs>(std::llround(seconds * 1e12));
}

}  // namespace cnc::test
