// Inputs within the machine: a job's coordinates, arc radii, feeds and length checked against what the machine
// and the architecture's counters can hold, before anything is simulated (BadInput naming the file and line, or
// the scenario keys). Without these a huge coordinate reached the planners as a step count no counter holds
// (the atmega PC program split it into 10^10 commands), an arc of 10^24 mm radius ran as 0 steps, and a move
// slower than the hardware's slowest step ran until the time limit.
#pragma once
#include "host/core/gcode.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

// The longest job cncsim simulates, s: the largest scenario.max_sim_s (11.6 days of machine time; the
// picosecond clock holds 106 days).
inline constexpr double kMaxJobS = 1e6;

// Every programmed move: its path (ends, arc extremes) and arc radius within host::kMaxPositionSteps on each axis (machine.hpp), the
// job's time at its feeds (plus its dwells and pauses) within kMaxJobS, and on spi-fpga each cutting move's feed
// no slower than the rate word's slowest step.
void check_job_limits(const host::Program& program, const Scenario& s);

// fpga-uart: the NUMERATOR of each axis (clock x 60 / steps per mm) must fit the init packet's uint32 (seed 000
// §3.4.6); BadInput naming the machine keys that set it.
void check_numerators(const Scenario& s);

}  // namespace cnc::sim
