// A serial link's faults as the report shows them: the frames a faulty wire hit, the USB latency spikes
// (faults.usb_spike_*) on the CP2102 of every architecture with a USB serial link, and the host program's stall
// (faults.host_stall_*), each with what it did.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "host/core/host_stall.hpp"
#include "run/arch_run.hpp"
#include "scenario/fault_settings.hpp"
#include "uart/core/cp2102_config.hpp"
#include "uart/cp2102.hpp"
#include "uart/faulty_line.hpp"

namespace cnc::sim {

// The frames a faulty UART wire carried and hit (uart/faulty_line.hpp), as every report with line faults shows them.
[[nodiscard]] nlohmann::json faulty_line_json(const uart::FaultyLineStats& line);

// `link` with the spikes of `f`, drawn from faults.seed.
[[nodiscard]] uart::Cp2102Config with_usb_spikes(uart::Cp2102Config link, const FaultSettings& f);
// With spikes asked for: those that delayed data, each direction, into the report's `usb_spikes` and its text.
void report_usb_spikes(const FaultSettings& f, const uart::Cp2102& cp2102, ArchRun& run);

// The host program's stall window of the faults.
[[nodiscard]] host::StallWindow stall_window(const HostStall& stall);
// The stall asked for and how long it held the host program up (`held_ps`): the report's `host_stall` and its line.
[[nodiscard]] nlohmann::json host_stall_json(const HostStall& stall, TimePs held_ps);
[[nodiscard]] std::string host_stall_text(const HostStall& stall, TimePs held_ps);
// With a stall asked for: host_stall_json into the report's faults section, and its line.
void report_host_stall(const HostStall& stall, TimePs held_ps, ArchRun& run);

}  // namespace cnc::sim
