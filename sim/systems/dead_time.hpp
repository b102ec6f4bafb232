// Where the dead time between two fpga-uart moves goes: from the last STEP of one move to the first STEP of
// the next, split at every hand-over of the stop-and-wait loop (seed 000 §4.4). The parts add up exactly.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fpga/core/fpga_records.hpp"
#include "host/sender.hpp"
#include "metrics/metrics.hpp"
#include "run/arch_run.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim {

struct GapBreakdown {
    int after_move = 0;        // 1-based move the gap follows
    TimePs step_tail_ps = 0;   // last STEP rise -> busy falls (rest of the last period + DONE)
    TimePs ack_wire_ps = 0;    // busy falls -> ACK stop bit ends at the CP2102 (tx_start + 10 bits)
    TimePs usb_in_ps = 0;      // ACK received -> the host sees it (USB frame + driver latency)
    TimePs job_wait_ps = 0;    // the job's own waits slept by the host: G4 dwell, M0 pause, Z moves
    TimePs host_ps = 0;        // the rest until the host calls write() for the next packet (processing)
    TimePs usb_out_ps = 0;     // write() -> the packet reaches the CP2102 (OS latency + USB frame)
    TimePs packet_wire_ps = 0; // first start bit -> pkt_valid (11 frames; uart_rx takes the stop bit mid-bit)
    TimePs fpga_setup_ps = 0;  // pkt_valid -> first STEP (SETUP, DIR settle: 203 clocks)
    TimePs total_ps = 0;       // = first STEP of the next move - last STEP of this one
};

struct DeadTimeBreakdown {
    std::size_t gap_count = 0;
    GapBreakdown sum, max;            // each part summed and at its largest over the gaps (after_move unused)
    std::vector<GapBreakdown> gaps;   // every gap, when kept (a long job has one per packet)
    double utilisation_to_fpga_pct = 0.0;    // host -> FPGA line busy time over the job time
    double utilisation_from_fpga_pct = 0.0;
};

// An executed piece's first and last STEP rise on any axis (none: it stepped no axis), which bound the gaps.
struct PieceSteps {
    std::optional<TimePs> t_first_ps, t_last_ps;
};
[[nodiscard]] PieceSteps piece_steps(const metrics::MoveMetrics& piece);

// `pieces`: the run's executed pieces as measured (one per packet). `cp2102`: its TX log thinned to each motion
// packet's first byte (Cp2102::thin_tx_log(host::kInitPacketBytes, host::kMotionPacketBytes)). `keep_gaps`: keep every gap's breakdown (the
// detailed report and the dead-time plot list them), not only the sums and maxima.
DeadTimeBreakdown dead_time_breakdown(const std::vector<PieceSteps>& pieces, TimePs t_job_start_ps,
                                      TimePs t_job_end_ps, const std::vector<fpga::PacketRecord>& records,
                                      const std::vector<host::SentPacket>& sent, const uart::Cp2102& cp2102,
                                      bool keep_gaps);
// `detail`: with every gap's breakdown (per_gap: the gaps must have been kept); without, the mean and the max of
// each part.
nlohmann::json to_json(const DeadTimeBreakdown& d, bool detail);
std::string summary_text(const DeadTimeBreakdown& d);
// The same split per gap for the dead-time plot (the gaps must have been kept).
std::vector<GapCauses> gap_causes(const DeadTimeBreakdown& d);

}  // namespace cnc::sim
