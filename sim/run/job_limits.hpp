// Inputs within the machine: a job's coordinates, arc radii, feeds and length checked against what the machine
// and the architecture's counters can hold, before anything is simulated (BadInput naming the file and line, or
// the scenario keys). Without these a huge coordinate reached the planners as a step count no counter holds
// (the seed 003 PC program split it into 10^10 commands), an arc of 10^24 mm radius ran as 0 steps, and a move
// slower than the hardware's slowest step ran until the time limit.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "architectures/architecture.hpp"
#include "host/core/gcode.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

// The longest job cncsim simulates, s: the largest scenario.max_sim_s (11.6 days of machine time; the
// picosecond clock holds 106 days).
inline constexpr double kMaxJobS = 1e6;

// Every programmed move, one at a time as the job is read: its path (ends, arc extremes) and arc radius within
// host::kMaxPositionSteps on each axis (machine.hpp), the job's time at its feeds (plus its dwells and pauses)
// within kMaxJobS, then what the architecture checks of a move (Architecture::check_move). `s` and `architecture`
// must outlive it.
class JobLimits {
public:
    JobLimits(const Scenario& s, const Architecture& architecture, std::string filename);
    // Move number i; `waits` holds at least every wait before it (Program::waits so far).
    void check(const host::ProgrammedMove& move, std::size_t i, const std::vector<host::HostWait>& waits);
    // After the last move, with every wait.
    void finish(const std::vector<host::HostWait>& waits);

private:
    const Scenario& m_s;
    const Architecture& m_architecture;
    std::string m_file;
    double m_job_s = 0.0;
    std::size_t m_wait = 0;  // waits counted
};

}  // namespace cnc::sim
