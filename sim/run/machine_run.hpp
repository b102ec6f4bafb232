// The one run of every architecture that drives the shared machine: its controller elaborated and bound to the
// machine's pins, the recorder and the VCD, the time budget, the metrics streamed as the run goes (or computed from
// the whole logs), the simulation, the mechanics' end, the metrics' input and the report. The controller
// (run/controller.hpp) adds only what is its own.
#pragma once
#include <functional>
#include <memory>

#include "run/arch_run.hpp"
#include "run/controller.hpp"
#include "run/job.hpp"
#include "run/machine.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

// Builds the controller for the scenario and job, its outputs bound to `pins` (before anything is simulated:
// BadInput for what the scenario or job asks that it cannot do).
using MakeController = std::function<std::unique_ptr<Controller>(const Scenario&, const Job&, MachinePins&)>;

[[nodiscard]] ArchRun run_on_machine(const Scenario& s, const Job& job, const MakeController& make);

}  // namespace cnc::sim
