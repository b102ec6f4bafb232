// The host program's timing around each write and ACK (send_steps.py of seed 000 appendix A.2, and the seed 003 PC
// program that shares it): settle, init gap, ACK timeout, its own work and the OS write latency.
#pragma once
#include "common/units.hpp"
#include "host/core/host_stall.hpp"

namespace cnc::host {

// Our option on seed 000 §7.2's proposal of a CRC (protocol.crc = "crc16", frames in packet_codec.hpp): each packet
// checked, a NAK or a lost ACK answered by sending it again.
struct PacketCheckConfig {
    bool crc = false;
    int retries = 3;                         // sends of a packet after its first, before the seed's timeout rule
    TimePs retry_delay_ps = 150 * kPsPerMs;  // before a resend: past the FPGA's 100 ms watchdog (seed 000 §5.2.3),
                                             // so that a partial packet left by a lost byte is gone
};

struct SenderConfig {
    TimePs settle_ps = 300 * kPsPerMs;             // send_steps.py: time.sleep(0.3) after opening the port
    TimePs init_gap_ps = 50 * kPsPerMs;            // time.sleep(0.05) after the init packet (it is not ACKed)
    TimePs ack_timeout_ps = 10 * kPsPerSec;        // ACK_TIMEOUT_SEC = 10.0
    TimePs packet_processing_ps = 200 * kPsPerUs;  // CPython loop, struct.pack, progress print: typical 0.1-0.5 ms
    TimePs write_latency_ps = 100 * kPsPerUs;      // write() through the VCP driver to the USB request
    bool continue_on_timeout = false;  // the script asks "Continue anyway? [y/N]"; with no terminal: N, abort
    PacketCheckConfig check;
    // With the FPGA's packet queue (fpga.queue_depth, common/queue_protocol.hpp): packets kept in flight at most;
    // 0, the seed's stop-and-wait.
    int queue_depth = 0;
    StallWindow stall;  // a fault: none by default
};

}  // namespace cnc::host
