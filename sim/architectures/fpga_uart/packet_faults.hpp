// What the faults on the link did to the job's packets: each packet step_gen saw is laid against the one the host
// was sending when it arrived (stop-and-wait keeps one packet in flight: the last taken before its pkt_valid; with
// the packet queue, which takes them in order, by their order),
// so a byte lost or a packet misframed never shifts the pairing of the packets after it. A packet the FPGA ran
// with other fields than the host sent is a silent corruption (the seed's packets carry no check); a packet no
// record ran at all is lost; a second run of a packet, or a record before any packet, is extra. The steps each
// error leaves at the job's end are the executed steps less the sent ones.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "common/units.hpp"
#include "fpga/core/packet_decoder_core.hpp"

namespace cnc::sim::fpga_uart {

struct HostPacket {
    TimePs t_taken_ps = 0;  // the script took it to send (it writes it after, and takes the next after its reply)
    int gcode_line = 0;     // 0: unknown
    fpga::MotionFields fields;
};

struct FpgaPacket {
    TimePs t_pkt_valid_ps = 0;
    bool accepted = false;  // step_gen ran it (false: it arrived while busy and was ignored)
    fpga::MotionFields fields;
};

using StepPair = std::array<std::int64_t, 2>;  // x, y

struct SilentCorruption {
    int segment = 0;  // 1-based, as the script counts
    int gcode_line = 0;
    fpga::MotionFields sent;
    fpga::MotionFields executed;
    StepPair error_steps{};  // executed less sent
};

struct PacketFaults {
    std::int64_t sent = 0;
    std::int64_t executed_as_sent = 0;  // packets run once with the fields sent
    std::int64_t executed_wrong = 0;    // silent corruptions (records accepted with other fields)
    std::int64_t lost = 0;              // packets no record ran, as sent or otherwise
    std::int64_t extra = 0;             // runs of a packet already run as sent, or before any was sent
    std::int64_t ignored = 0;           // records step_gen ignored (busy), whatever their fields
    std::vector<SilentCorruption> silent;
    StepPair job_end_error_steps{};  // every executed record's steps less every sent packet's
};

// `sent` and `received` in time order. `in_order`: the packet queue takes each packet once and in order (record k
// of those step_gen ran is packet k), instead of the pairing by time.
[[nodiscard]] PacketFaults packet_faults(const std::vector<HostPacket>& sent, const std::vector<FpgaPacket>& received,
                                         bool in_order = false);

}  // namespace cnc::sim::fpga_uart
