// The progress display with its own wall clock, from its construction (the simulation's start): what a run calls
// between its slices, whichever way it runs them (run/simulate.hpp, or an architecture's own loop).
#pragma once
#include <chrono>
#include <ostream>
#include <string>

#include "run/progress.hpp"

namespace cnc::sim {

class TimedProgress {
public:
    TimedProgress(std::ostream& out, ProgressStyle style, double expected_s, std::string label = "");
    void update(double sim_s) { m_progress.update(sim_s, wall_s()); }
    void finish(double sim_s) { m_progress.finish(sim_s, wall_s()); }
    [[nodiscard]] double wall_s() const;

private:
    Progress m_progress;
    std::chrono::steady_clock::time_point m_start;
};

}  // namespace cnc::sim
