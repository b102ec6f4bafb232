#include "fpga/core/packet_queue_core.hpp"

#include <stdexcept>
#include <string>

namespace cnc::fpga {

namespace qp = queue_protocol;

PacketQueueCore::PacketQueueCore(int depth) : m_depth(depth) {
    if (depth < 1 || depth > qp::kMaxDepth) {
        throw std::invalid_argument("queue depth " + std::to_string(depth) + " (allowed 1 .. " +
                                    std::to_string(qp::kMaxDepth) + ")");
    }
}

PacketQueueCore::Taken PacketQueueCore::on_packet(const MotionFields& f) {
    const int ahead = qp::seq_distance(m_next_seq, f.seq);
    if (ahead == 0 && static_cast<int>(m_fifo.size()) < m_depth) {
        m_fifo.push_back(f);
        m_next_seq = (m_next_seq + 1) % qp::kSeqModulo;
        ++m_queued;
        return Taken::Queued;
    }
    // Behind by 1 .. kMaxDepth: a packet queued already, sent again because its status was lost.
    if (ahead >= qp::kSeqModulo - qp::kMaxDepth) {
        ++m_again;
        return Taken::Again;
    }
    ++m_refused_count;
    return Taken::Refused;
}

bool PacketQueueCore::pop(MotionFields& out) {
    if (m_fifo.empty()) return false;
    out = m_fifo.front();
    m_fifo.pop_front();
    m_running = true;
    return true;
}

qp::Status PacketQueueCore::status(bool refused) const {
    return {m_next_seq, m_depth - static_cast<int>(m_fifo.size()), m_running, refused};
}

}  // namespace cnc::fpga
