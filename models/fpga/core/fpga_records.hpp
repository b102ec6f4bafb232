// What the FPGA model logs for reports: one record per pkt_valid and per cfg_valid, plus counters.
// Plain data, filled during the run and read after it.
#pragma once
#include <cstdint>

#include "common/units.hpp"

namespace cnc::fpga {

struct PacketRecord {            // one pkt_valid (accepted by step_gen or ignored because busy)
    TimePs t_pkt_valid_ps = -1;  // edge at which pkt_valid is high
    std::uint8_t motion = 0;     // decoder output motion[1:0]
    std::int32_t steps_x = 0;
    std::int32_t steps_y = 0;
    std::uint16_t feed = 0;
    bool accepted = false;              // false: step_gen was not IDLE, the packet is lost (seed 000 §5.2.4)
    std::uint32_t period_x_cycles = 0;  // as computed in DIR_WAIT (after the wrap if Wrap32)
    std::uint32_t period_y_cycles = 0;
    bool period_overflow = false;  // (num/feed)*abs_dom exceeded 2^32-1 (flagged in either mode)
    TimePs t_run_start_ps = -1;    // first RUN cycle; -1 if ignored or zero-length (no RUN state)
    TimePs t_busy_fall_ps = -1;    // DONE edge (busy falls); scheduled time if the run stopped before it
    TimePs t_ack_start_ps = -1;    // tx_start edge, or -1 if the ACK was dropped (or not reached yet)
};

struct InitRecord {
    TimePs t_cfg_valid_ps = -1;  // edge at which cfg_valid is high
    std::uint32_t num_x = 0;
    std::uint32_t num_y = 0;
    bool applied = false;  // latched by step_gen: init_packet_wired and step_gen IDLE
};

struct FpgaStats {
    std::uint64_t bytes_received = 0;   // uart_rx bytes with a good stop bit (rx_valid pulses)
    std::uint64_t framing_errors = 0;   // uart_rx bytes dropped for a low stop bit
    std::uint64_t watchdog_resets = 0;  // packet_decoder 100 ms timeouts that cleared a partial packet
    std::uint64_t acks_sent = 0;        // tx_start pulses
    std::uint64_t acks_dropped = 0;     // busy fell while uart_tx was busy: no ACK (seed 000 §4.13), none pending
    std::uint64_t crc_errors = 0;       // with the packet check: packets whose CRC failed
    std::uint64_t naks_sent = 0;        // their NAKs sent (uart_tx was idle)
    std::uint64_t repeats = 0;          // good packets sent again (their ACK lost): not run twice
    std::uint64_t queued = 0;           // with the packet queue: packets queued, each once
    std::uint64_t answered_again = 0;   // packets queued already, sent again (their status lost): not queued twice
    std::uint64_t refused = 0;          // packets out of order or with no slot: not queued
    std::uint64_t statuses_sent = 0;
    TimePs halted_at_ps = -1;  // with the e-stop input: the edge step_gen halted at (-1: never)
};

}  // namespace cnc::fpga
