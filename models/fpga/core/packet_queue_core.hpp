// packet_queue without timing: our option on seed 000 §7.2's command queue and FIFO packet buffer (fpga.queue_depth).
// Numbered motion packets (common/queue_protocol.hpp) are queued in order, at most `depth` waiting for step_gen,
// each taken once: the next number expected is queued if a slot is free, a number already queued is answered
// again (the host lost its status) and anything else is refused. The module adds the clock edges and the wiring to
// step_gen and uart_tx.
#pragma once
#include <cstdint>
#include <deque>

#include "common/queue_protocol.hpp"
#include "fpga/core/packet_decoder_core.hpp"

namespace cnc::fpga {

class PacketQueueCore {
public:
    enum class Taken { Queued, Again, Refused };

    // depth: 1 .. queue_protocol::kMaxDepth.
    explicit PacketQueueCore(int depth);

    // A motion packet the decoder completed with a good CRC.
    Taken on_packet(const MotionFields& f);
    // step_gen is free: the oldest queued move goes to it (false if none is queued).
    bool pop(MotionFields& out);
    // step_gen ended its move without a next one.
    void on_move_done() { m_running = false; }

    // The status as of now; `refused`: it answers a packet that was not queued.
    [[nodiscard]] queue_protocol::Status status(bool refused) const;
    [[nodiscard]] bool empty() const { return m_fifo.empty(); }
    // A move handed to step_gen has not ended yet.
    [[nodiscard]] bool running() const { return m_running; }
    [[nodiscard]] std::uint64_t queued() const { return m_queued; }
    [[nodiscard]] std::uint64_t answered_again() const { return m_again; }
    [[nodiscard]] std::uint64_t refused() const { return m_refused_count; }

private:
    const int m_depth;
    std::deque<MotionFields> m_fifo;
    int m_next_seq = 0;
    bool m_running = false;
    std::uint64_t m_queued = 0;
    std::uint64_t m_again = 0;
    std::uint64_t m_refused_count = 0;
};

}  // namespace cnc::fpga
