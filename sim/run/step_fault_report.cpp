#include "run/step_fault_report.hpp"

#include <fmt/format.h>

namespace cnc::sim {

void add_step_fault_report(const Machine& machine, const Scenario& s, ArchRun& run) {
    const mech::Drv8825Stats& x = machine.driver_x().stats();
    const mech::Drv8825Stats& y = machine.driver_y().stats();
    // A lost pulse leaves the tool one microstep short in the direction it would have stepped.
    const double off_x_mm = static_cast<double>(-x.lost_net_steps) / s.machine.x.steps_per_mm();
    const double off_y_mm = static_cast<double>(-y.lost_net_steps) / s.machine.y.steps_per_mm();
    run.details["step_faults"] = {{"step_loss_rate", s.faults.step_loss_rate},
                                  {"seed", s.faults.seed},
                                  {"lost", {x.lost_to_fault, y.lost_to_fault}},
                                  {"lost_net_steps", {x.lost_net_steps, y.lost_net_steps}},
                                  {"tool_off_mm", {off_x_mm, off_y_mm}}};
    run.details_text += fmt::format(
        FMT_STRING("STEP pulses lost on the drivers' inputs (rate {:g}): X {} (net {:+d}), Y {} (net {:+d}); the tool "
                   "ends {:+.4f} mm, {:+.4f} mm off for them\n"),
        s.faults.step_loss_rate, x.lost_to_fault, x.lost_net_steps, y.lost_to_fault, y.lost_net_steps, off_x_mm,
        off_y_mm);
}

}  // namespace cnc::sim
