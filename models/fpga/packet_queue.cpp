#include "fpga/packet_queue.hpp"

namespace cnc::fpga {

PacketQueue::PacketQueue(const sc_core::sc_module_name& name, const FpgaConfig& cfg)
    : sc_module(name),
      motion("motion"),
      seq("seq"),
      steps_x("steps_x"),
      steps_y("steps_y"),
      feed_rate("feed_rate"),
      laser_high("laser_high"),
      pkt_valid("pkt_valid"),
      crc_error("crc_error"),
      busy("busy"),
      q_motion("q_motion"),
      q_steps_x("q_steps_x"),
      q_steps_y("q_steps_y"),
      q_feed_rate("q_feed_rate"),
      q_laser_high("q_laser_high"),
      q_pkt_valid("q_pkt_valid"),
      status_req("status_req"),
      m_clock(clock_grid(cfg)),
      m_core(cfg.queue_depth),
      m_writer("writer") {
    SC_HAS_PROCESS(PacketQueue);
    SC_METHOD(on_pkt_valid);
    sensitive << pkt_valid;
    dont_initialize();
    SC_METHOD(on_crc_error);
    sensitive << crc_error;
    dont_initialize();
    SC_METHOD(on_busy);
    sensitive << busy;
    dont_initialize();
}

queue_protocol::Status PacketQueue::take_status() {
    const queue_protocol::Status s = m_core.status(m_refused);
    m_refused = false;
    return s;
}

void PacketQueue::request_status(std::int64_t edge, bool refused) {
    if (edge >= m_halt_edge) return;
    m_refused = m_refused || refused;
    if (edge == m_status_edge) return;
    m_status_edge = edge;
    m_writer.at(m_clock.at(edge), [this] { status_req.write(true); });
    m_writer.at(m_clock.at(edge + 1), [this] { status_req.write(false); });
}

void PacketQueue::hand_over(std::int64_t edge) {
    MotionFields f;
    if (edge >= m_halt_edge || !m_core.pop(f)) return;
    const TimePs t = m_clock.at(edge);
    m_issued.push_back({t, f});
    MotionOutputs{q_motion, q_steps_x, q_steps_y, q_feed_rate, q_laser_high, q_pkt_valid}.put(m_writer, m_clock, edge,
                                                                                              f);
}

// The decoder's pkt_valid high at edge k: the packet is taken at k+1 and, step_gen being free, handed over there.
void PacketQueue::on_pkt_valid() {
    ++m_activations;
    if (!pkt_valid.read()) return;
    const std::int64_t edge = m_clock.last_at_or_before(now_ps()) + 1;
    const MotionFields f{motion.read(),    steps_x.read(), steps_y.read(),
                         feed_rate.read(), seq.read(),     laser_high.read()};
    const PacketQueueCore::Taken taken = m_core.on_packet(f);
    if (taken == PacketQueueCore::Taken::Queued && !m_core.running()) hand_over(edge);
    request_status(edge, taken == PacketQueueCore::Taken::Refused);
}

void PacketQueue::on_crc_error() {
    ++m_activations;
    if (!crc_error.read()) return;
    request_status(m_clock.last_at_or_before(now_ps()) + 1, true);
}

// busy fell at edge f: step_gen is IDLE at f+1, where it sees a pkt_valid of edge f.
void PacketQueue::on_busy() {
    ++m_activations;
    if (busy.read()) return;
    const std::int64_t f = m_clock.last_at_or_before(now_ps());
    m_core.on_move_done();
    hand_over(f);
    request_status(f, false);
}

}  // namespace cnc::fpga
