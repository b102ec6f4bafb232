// Where the dead time between two fpga-uart packets goes (between programmed moves, or inside one between an arc's
// chords): from the last STEP of one packet to the first STEP of the next, split at every hand-over of the
// stop-and-wait loop (seed 000 §4.14). The parts add up exactly.
#pragma once
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "common/record_log.hpp"
#include "fpga/board.hpp"
#include "host/sender.hpp"
#include "metrics/metrics.hpp"
#include "run/arch_run.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim {

struct GapBreakdown {
    int after_packet = 0;       // 1-based motion packet (executed piece) the gap follows
    TimePs step_tail_ps = 0;    // last STEP rise -> busy falls (rest of the last period + DONE)
    TimePs ack_wire_ps = 0;     // busy falls -> ACK stop bit ends at the CP2102 (tx_start + 10 bits)
    TimePs usb_in_ps = 0;       // ACK received -> the host sees it (USB frame + driver latency)
    TimePs job_wait_ps = 0;     // the job's own waits slept by the host: G4 dwell, M0 pause, Z moves
    TimePs host_ps = 0;         // the rest until the host calls write() for the next packet (processing)
    TimePs usb_out_ps = 0;      // write() -> the packet reaches the CP2102 (OS latency + USB frame)
    TimePs packet_wire_ps = 0;  // first start bit -> pkt_valid (11 frames; uart_rx takes the stop bit mid-bit)
    TimePs fpga_setup_ps = 0;   // pkt_valid -> first STEP (SETUP, DIR settle: 203 clocks)
    TimePs total_ps = 0;        // = first STEP of the next move - last STEP of this one
};

struct DeadTimeBreakdown {
    std::size_t gap_count = 0;
    GapBreakdown sum, max;                 // each part summed and at its largest over the gaps (after_packet unused)
    std::vector<GapBreakdown> gaps;        // every gap, when kept (a long job has one per packet)
    double utilisation_to_fpga_pct = 0.0;  // host -> FPGA line busy time over the job time
    double utilisation_from_fpga_pct = 0.0;
};

// An executed piece's first and last STEP rise on any axis (none: it stepped no axis), which bound the gaps.
struct PieceSteps {
    std::optional<TimePs> t_first_ps, t_last_ps;
};
[[nodiscard]] PieceSteps piece_steps(const metrics::MoveMetrics& piece);

// The split folded gap by gap as the run goes, so that nothing per packet stays once its gap is measured. Gap i
// (after piece i) is folded once each input it reads is final: pieces i and i+1 measured, packet i+1 sent and its
// ACK read (the sender logs it then), step_gen past packet i's busy fall (its ACK is decided then) and, when that
// ACK was sent, its byte received by the CP2102. Gaps are folded in order; at the end of the run what is missing
// stays missing and the gap is left out.
class DeadTimeFold {
public:
    // `keep_gaps`: keep every gap's breakdown (the detailed report and the dead-time plot list them), not only the
    // sums and maxima.
    explicit DeadTimeFold(bool keep_gaps) : m_keep_gaps(keep_gaps) {}
    // The run's executed pieces in order, as measured (one per packet).
    void add_piece(const PieceSteps& piece) { m_pieces.push_back(piece); }
    // Folds the gaps final at `now_ps`; `ended`: the run is over, fold every gap there is. `cp2102`: its TX log
    // thinned to each motion packet's first byte (Cp2102::thin_tx_log with the init and motion packets' lengths).
    void fold(TimePs now_ps, bool ended, const fpga::Board& fpga, const RecordLog<host::SentPacket>& sent,
              const uart::Cp2102& cp2102);
    // What the gaps still to fold read, from which on the records must be kept: the FPGA's packets, the sender's
    // and the CP2102's (thinned) TX log from packet next_packet(), its RX log from byte next_rx_byte().
    [[nodiscard]] std::size_t next_packet() const { return m_next_gap; }
    [[nodiscard]] std::size_t next_rx_byte() const { return m_next_rx_byte; }
    // The split of the whole job (every gap must have been folded: fold(..., true, ...)).
    [[nodiscard]] DeadTimeBreakdown finish(TimePs t_job_start_ps, TimePs t_job_end_ps, const uart::Cp2102& cp2102);

private:
    const bool m_keep_gaps;
    DeadTimeBreakdown m_d;
    std::deque<PieceSteps> m_pieces;  // from piece m_first_piece on: the ones gaps still to be folded read
    std::size_t m_first_piece = 0;
    std::size_t m_next_gap = 0;      // the gap after piece m_next_gap is the next one to fold
    std::size_t m_next_rx_byte = 0;  // the last ACK found: a later gap's ACK is not before it
};

// `detail`: with every gap's breakdown (per_gap: the gaps must have been kept); without, the mean and the max of
// each part.
nlohmann::json to_json(const DeadTimeBreakdown& d, bool detail);
std::string summary_text(const DeadTimeBreakdown& d);
// The same split per gap for the dead-time plot (the gaps must have been kept).
std::vector<GapCauses> gap_causes(const DeadTimeBreakdown& d);

}  // namespace cnc::sim
