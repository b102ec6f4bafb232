// Builders of synthetic STEP/DIR traces and moves with known answers for the metrics tests.
#pragma once
#include <string>
#include <vector>

#include "common/edge_log.hpp"
#include "common/units.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics::test {

inline constexpr TimePs kFpgaClockPs = 20'000;     // seed 000: 50 MHz FPGA clock
inline constexpr double kMicrostepMm = 1.0 / 160;  // seed 000 machine: 160 steps/mm

// n times t0, t0 + period, ...
inline std::vector<TimePs> grid(TimePs t0_ps, TimePs period_ps, std::size_t n) {
    std::vector<TimePs> t;
    for (std::size_t k = 0; k < n; ++k) t.push_back(t0_ps + static_cast<TimePs>(k) * period_ps);
    return t;
}

// A STEP log with a pulse of `high_ps` starting at each rising time.
inline EdgeLog step_log(const std::vector<TimePs>& rises, TimePs high_ps = 2 * kPsPerUs,
                        const std::string& name = "step_x") {
    EdgeLog log{name, false, {}};
    for (const TimePs t : rises) {
        log.add(t, true);
        log.add(t + high_ps, false);
    }
    return log;
}

// A DIR log toggling at each time, starting low.
inline EdgeLog dir_log(const std::vector<TimePs>& changes, const std::string& name = "dir_x") {
    EdgeLog log{name, false, {}};
    bool level = false;
    for (const TimePs t : changes) {
        level = !level;
        log.add(t, level);
    }
    return log;
}

inline AxisTrace axis(const std::vector<TimePs>& rises, const std::string& name = "x") {
    AxisTrace a;
    a.name = name;
    a.step = step_log(rises, 2 * kPsPerUs, "step_" + name);
    a.dir = EdgeLog{"dir_" + name, true, {}};  // positive direction
    return a;
}

inline MoveSpec line_move(int index, geom::Vec2 from, geom::Vec2 to, double feed_mm_per_min, TimePs t_begin_ps,
                          TimePs t_end_ps) {
    MoveSpec m;
    m.index = index;
    m.line = index + 1;
    m.path = geom::Segment::line(from, to);
    m.from_mm = from;
    m.to_mm = to;
    m.feed_mm_per_min = feed_mm_per_min;
    m.t_begin_ps = t_begin_ps;
    m.t_end_ps = t_end_ps;
    return m;
}

}  // namespace cnc::metrics::test
