// The host side of the USB-UART link that two of the source designs share: a PC program writing through a CP2102
// (seed 000's send_steps.py and seed 003's PC program). The keys [link] (the bridge) and the host program's timing
// (host.settle_s .. host.on_timeout), read by one reader for every architecture that drives such a link.
#pragma once
#include "host/core/sender_config.hpp"
#include "scenario/key_reader.hpp"
#include "uart/core/cp2102_config.hpp"

namespace cnc::sim {

struct SerialHostSettings {
    uart::Cp2102Config link;
    host::SenderConfig sender;
};

void read_serial_host_settings(KeyReader& r, SerialHostSettings& s);

}  // namespace cnc::sim
