// How long a job should take, worked out before it is simulated: the 100 % of the progress display and the
// default simulated-time limit (scenario.max_sim_s). SystemC-free.
//
//   expected_s = startup_s + link_s + host waits + sum over the programmed moves of (length / speed + ramp_s(speed))
//   limit_s    = 2 x expected_s + 1 s x moves + 10 s
//
// A move's length is its path (arcs by arc length); its speed is its programmed feed (rapids at the rapid feed
// the interpreter gives them), held to what each axis can do (ArchPace). The limit's margins cover what the
// estimate leaves out: the seed 000 packet feed rounded to whole mm/min (up to 2x slower at the lowest
// feeds), the speed changes of an architecture that has no ramp_s. A run that needs more is stuck or far off its
// job; scenario.max_sim_s set in the scenario replaces the limit.
#pragma once
#include <cstddef>
#include <functional>
#include <limits>
#include <string>

#include "host/core/gcode.hpp"

namespace cnc::sim {

// What an architecture does to a job's time beyond the programmed moves at their feeds.
struct ArchPace {
    // Fastest each axis steps, mm/s (seed 003: the OCR = 0 rate; a planner: its axis limit). A line's
    // path speed is held so that no axis exceeds its own; an arc's to the smaller of the two (its tangent turns).
    double max_speed_x_mm_per_s = std::numeric_limits<double>::infinity();
    double max_speed_y_mm_per_s = std::numeric_limits<double>::infinity();
    double startup_s = 0.0;  // before the first move: port settle, init packet
    double link_s = 0.0;     // every command's trip over the host link, counted as if nothing overlapped it
    // Time to speed up to and stop from a move's speed beyond length / speed (a planner's ramps); none if empty.
    std::function<double(double speed_mm_per_s)> ramp_s;
};

struct JobEstimate {
    double expected_s = 0.0;
    double limit_s = 0.0;
    std::size_t moves = 0;
};

// Every move's feed must be > 0 (the interpreter refuses F0, rapids carry the rapid feed).
[[nodiscard]] JobEstimate estimate_job(const host::Program& program, const ArchPace& pace);

// The same, one move at a time, for a streamed job; `waits_s`: every host wait of the job.
class EstimateSum {
public:
    EstimateSum(double waits_s, const ArchPace& pace);
    void add(const host::ProgrammedMove& move);
    [[nodiscard]] JobEstimate finish() const;

private:
    ArchPace m_pace;
    JobEstimate m_e;
};

// The limit's sum with this job's numbers: "2 x 5.200 s + 1 s x 6 moves + 10 s".
[[nodiscard]] std::string limit_formula(const JobEstimate& estimate);

}  // namespace cnc::sim
