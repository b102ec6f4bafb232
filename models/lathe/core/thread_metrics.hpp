// The thread a multi-pass cut leaves (docs/metrics.md, "Lathe"): pitch error per spindle revolution and phase error
// between passes, from the carriage position at each spindle pulse of each pass.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

namespace cnc::lathe {

// One cutting pass: x_mm[j] is the carriage advance along the cut direction at the j-th spindle pulse after the
// pass's start index (j = 0: at the index), from one origin for every pass.
struct ThreadPass {
    std::vector<double> x_mm;
};

struct ThreadMetrics {
    // Over every spindle revolution of a pass (index to index: pulse j to j + pulses_per_rev, j a multiple of
    // pulses_per_rev) inside the common length: carriage advance - pitch.
    double pitch_error_mean_um = 0.0;
    double pitch_error_max_um = 0.0;  // max |.|
    int revolutions = 0;
    // The thread's mean pitch as a gauge over many crests sees it: per pass the least-squares slope of the carriage
    // against the spindle revolutions over every pulse inside the common length, mean over the passes, - pitch.
    // The per-revolution figures above carry the motor's stop-and-go at the spindle pulses; the fit averages it.
    double pitch_fit_error_um = 0.0;
    // Pass k against pass 1 at the same spindle pulse, where both lie inside the common length: max |.|, and the
    // largest |mean| over the last common revolution (where the passes have settled).
    double phase_error_max_um = 0.0;
    double phase_error_end_um = 0.0;
    // Where that max lies: the later pass (index into the passes, 0 when there is none), the spindle pulse j
    // counted from the passes' start index, and its sign (+: the later pass ahead of pass 1 along the cut).
    std::size_t phase_error_max_pass = 0;
    std::size_t phase_error_max_pulse = 0;
    double phase_error_max_signed_um = 0.0;
    // The common length: the carriage range every pass covers.
    double common_from_mm = 0.0;
    double common_to_mm = 0.0;
};

// Pass k's carriage minus pass 1's at spindle pulse j, um (+: pass k ahead along the cut), where both lie inside
// the common length of `m`; none elsewhere. The phase error between passes above, at one pulse.
[[nodiscard]] std::optional<double> phase_error_um(const std::vector<ThreadPass>& passes, std::size_t k, std::size_t j,
                                                   const ThreadMetrics& m);

// The first settle_revolutions of every pass (the catch-up from the slip and the PID's slow settling) are left
// out of both errors; the common length is that of the whole passes. Passes without a common length give zero
// revolutions and no phase error.
[[nodiscard]] ThreadMetrics thread_metrics(const std::vector<ThreadPass>& passes, double pitch_mm, int pulses_per_rev,
                                           int settle_revolutions = 0);

}  // namespace cnc::lathe
