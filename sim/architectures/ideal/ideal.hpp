// The ideal architecture: the perfect controller, the baseline of every comparison. The job's trajectory as the
// planner plans it for the machine (its velocity, acceleration and jerk limits), with no link and no quantisation
// but the motor's own steps, turned into STEP/DIR edges at the exact instants the trajectory crosses each half
// step, driving the same DRV8825s, motors and carriage as every architecture. Its errors are the machine's own; what
// another architecture adds on top is that controller's cost. README.md in this folder says how.
#pragma once
#include "architectures/architecture.hpp"

namespace cnc::sim {

struct ArchRun;
struct Job;

namespace ideal {

// Its registry entry (architectures/registry.hpp).
struct Entry {
    static const Architecture& architecture();              // ideal.cpp
    static ArchRun run(const Scenario& s, const Job& job);  // ideal_controller.cpp
};

}  // namespace ideal

}  // namespace cnc::sim
