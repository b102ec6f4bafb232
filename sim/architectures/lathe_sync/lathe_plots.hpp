// The lathe's own plots for `cncsim run --plots` (sim/plots/arch_plot.hpp; docs/plots.md): the phase error of each
// pass against pass 1, and each pass's following error as the firmware counts it beside the carriage's, both over
// the spindle revolutions since the pass's start index.
#pragma once
#include <vector>

#include "lathe/core/thread_metrics.hpp"
#include "lathe/rig/lathe_rig.hpp"
#include "plots/arch_plot.hpp"

namespace cnc::sim::lathe_sync {

struct LathePlotInput {
    const std::vector<lathe::RecordedPass>& passes;
    // Per pass, the firmware's following error at each spindle pulse (lambda_list x k minus the motor pulses since
    // the start), motor pulses: what the report's following_error_max_pulses is the max of.
    const std::vector<std::vector<double>>& following_pulses;
    const lathe::ThreadMetrics& thread;  // with the settle revolutions left out: the report's phase error figures
    int settle_revolutions;
    double lambda_list;         // motor pulses per spindle pulse the ratio list realises
    double mm_per_motor_pulse;  // the carriage's travel per motor pulse
};

// `phase_error_passes` (none with a single pass) and `following_error_passes` (none without a pass).
[[nodiscard]] std::vector<ArchPlot> lathe_plots(const LathePlotInput& in);

}  // namespace cnc::sim::lathe_sync
