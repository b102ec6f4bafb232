// Builds the metrics input of `cncsim analyze` from the signals of a VCD: STEP/DIR (and enable) per axis, no
// moves, no tool positions, so only the pulse and driver-timing metrics (and travel when steps/mm is known) apply.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "metrics/pulse/enabled_steps.hpp"
#include "metrics/run_input.hpp"
#include "metrics/vcd/vcd_reader.hpp"

namespace cnc::metrics {

struct AxisSignalNames {
    std::string step;
    std::string dir;     // empty: no DIR signal (constant low)
    std::string enable;  // empty: the driver is always enabled
    EnableLevel enable_active = EnableLevel::ActiveLow;
};

// The --enable option "NAME", "NAME:active-low" or "NAME:active-high". Active low unless said: the driver whose
// timing analyze checks, the DRV8825, steps while its nENBL is low (DRV8825 datasheet, "nENBL"), as the enables of
// the other common step drivers do (A4988 ENABLE with its bar, TMC2208 ENN); counting the pulses while it is high
// would count those of a disabled driver. A colon followed by anything else is part of the name.
struct EnableOption {
    std::string name;
    EnableLevel active = EnableLevel::ActiveLow;
};
[[nodiscard]] EnableOption parse_enable_option(const std::string& text);

// A signal is named by its name or its dotted scope path (find_vcd_signal: step_x or driver_x.step_x). Each axis
// is labelled with its STEP signal's name as given; with an enable signal its STEP edges while the driver is
// disabled do not count (enabled_steps.hpp). The job window runs from the first to the last edge of the counted
// STEP and the DIR signals. Throws cnc::BadInput("<filename>: --step NAME", ...) (or --dir, --enable) naming the
// available 1-bit signals when a signal is missing, and what it is when the file has it with another width;
// BadInput("--steps-per-mm", ...) for a value <= 0.
[[nodiscard]] RunInput analyze_input(const VcdContents& vcd, const std::string& filename,
                                     const std::vector<AxisSignalNames>& axes,
                                     std::optional<double> steps_per_mm = std::nullopt);

}  // namespace cnc::metrics
