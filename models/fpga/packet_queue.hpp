// packet_queue: the packet queue between packet_decoder and step_gen (fpga.queue_depth, our option on seed 000 §7.2's
// command queue; the rules in core/packet_queue_core.hpp, the frame in common/queue_protocol.hpp). A packet the
// decoder completes at edge k is taken at k+1; the oldest queued move goes to step_gen with a one-clock pkt_valid
// at the first edge step_gen accepts it: at once when it is idle, else at the edge its busy falls (step_gen is
// IDLE at the next one), so that queued moves run back to back. Every packet answered and every move handed over or
// ended asks for a status (status_req, one clock).
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <systemc>

#include "common/record_log.hpp"
#include "fpga/core/fpga_config.hpp"
#include "fpga/core/packet_queue_core.hpp"
#include "fpga/packet_decoder.hpp"
#include "fpga/timed_writer.hpp"

namespace cnc::fpga {

class PacketQueue : public sc_core::sc_module {
public:
    // From packet_decoder.
    sc_core::sc_in<std::uint8_t> motion;
    sc_core::sc_in<std::uint8_t> seq;
    sc_core::sc_in<std::int32_t> steps_x;
    sc_core::sc_in<std::int32_t> steps_y;
    sc_core::sc_in<std::uint16_t> feed_rate;
    sc_core::sc_in<std::uint16_t> laser_high;
    sc_core::sc_in<bool> pkt_valid;
    sc_core::sc_in<bool> crc_error;
    // From step_gen.
    sc_core::sc_in<bool> busy;
    // To step_gen and laser_ctrl, as the decoder's outputs are without the queue.
    sc_core::sc_out<std::uint8_t> q_motion;
    sc_core::sc_out<std::int32_t> q_steps_x;
    sc_core::sc_out<std::int32_t> q_steps_y;
    sc_core::sc_out<std::uint16_t> q_feed_rate;
    sc_core::sc_out<std::uint16_t> q_laser_high;
    sc_core::sc_out<bool> q_pkt_valid;
    // To the status sender.
    sc_core::sc_out<bool> status_req;

    PacketQueue(const sc_core::sc_module_name& name, const FpgaConfig& cfg);

    // The status to send now; `refused` clears once read by take_status().
    [[nodiscard]] queue_protocol::Status take_status();
    // Every move handed to step_gen, in order (one per q_pkt_valid pulse).
    [[nodiscard]] const RecordLog<PacketDecoder::MotionOut>& issued() const { return m_issued; }
    void drop_issued_before(std::size_t end) { m_issued.drop_before(end); }
    [[nodiscard]] const PacketQueueCore& core() const { return m_core; }
    // The e-stop, seen through its synchroniser at edge `edge` (step_gen's halt): from that edge on nothing more is
    // handed to step_gen or answered.
    void halt_at(std::int64_t edge) { m_halt_edge = edge; }
    [[nodiscard]] std::uint64_t activations() const { return m_activations + m_writer.activations(); }

private:
    void on_pkt_valid();
    void on_crc_error();
    void on_busy();
    // The oldest queued move to step_gen at `edge`, if one is queued.
    void hand_over(std::int64_t edge);
    void request_status(std::int64_t edge, bool refused);

    const ClockGrid m_clock;
    PacketQueueCore m_core;
    TimedWriter m_writer;
    RecordLog<PacketDecoder::MotionOut> m_issued;
    bool m_refused = false;  // a refusal not told the host yet
    std::int64_t m_halt_edge = std::numeric_limits<std::int64_t>::max();
    std::int64_t m_status_edge = -1;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
