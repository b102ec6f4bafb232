// The host program's timing around each write and ACK (send_steps.py of seed 000 appendix A.2, and the seed 003 PC
// program that shares it): settle, init gap, ACK timeout, its own work and the OS write latency.
#pragma once
#include "common/units.hpp"

namespace cnc::host {

struct SenderConfig {
    TimePs settle_ps = 300 * kPsPerMs;             // send_steps.py: time.sleep(0.3) after opening the port
    TimePs init_gap_ps = 50 * kPsPerMs;            // time.sleep(0.05) after the init packet (it is not ACKed)
    TimePs ack_timeout_ps = 10 * kPsPerSec;        // ACK_TIMEOUT_SEC = 10.0
    TimePs packet_processing_ps = 200 * kPsPerUs;  // CPython loop, struct.pack, progress print: typical 0.1-0.5 ms
    TimePs write_latency_ps = 100 * kPsPerUs;      // write() through the VCP driver to the USB request
    bool continue_on_timeout = false;  // the script asks "Continue anyway? [y/N]"; with no terminal: N, abort
};

}  // namespace cnc::host
