// The USB latency spikes of a run's faults (faults.usb_spike_*) on the CP2102 of every architecture with a USB
// serial link, and what they did, as the report shows it.
#pragma once

#include "run/arch_run.hpp"
#include "scenario/fault_settings.hpp"
#include "uart/core/cp2102_config.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim {

// `link` with the spikes of `f`, drawn from faults.seed.
[[nodiscard]] uart::Cp2102Config with_usb_spikes(uart::Cp2102Config link, const FaultSettings& f);
// With spikes asked for: those that delayed data, each direction, into the report's `usb_spikes` and its text.
void report_usb_spikes(const FaultSettings& f, const uart::Cp2102& cp2102, ArchRun& run);

}  // namespace cnc::sim
