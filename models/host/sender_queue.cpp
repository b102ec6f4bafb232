// The sender with the FPGA's packet queue (SenderConfig::queue_depth, frame in common/queue_protocol.hpp):
// numbered packets kept in flight while the statuses give room, and go-back-N after a refusal or a silence.
#include <algorithm>
#include <deque>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "common/queue_protocol.hpp"
#include "common/sc_time.hpp"
#include "host/core/packet_codec.hpp"
#include "host/sender.hpp"

namespace cnc::host {

namespace qp = queue_protocol;

namespace {

struct InFlight {
    std::vector<std::uint8_t> bytes;  // numbered and followed by the CRC
    SentPacket sent;
    TimePs t_last_write_ps = 0;
};

std::vector<std::uint8_t> numbered_packet(const OutgoingPacket& packet, int seq) {
    std::vector<std::uint8_t> bytes = motion_frame(packet.bytes, packet.laser_high);
    bytes[0] = qp::with_seq(bytes[0], seq);
    return with_crc(bytes.data(), bytes.size());
}

// What the host knows of the FPGA's queue: its depth and the last status read.
struct QueueLink {
    int depth = 0;
    qp::Status status;

    // The moves sent have all run: every packet queued and the status since says nothing queued or running.
    [[nodiscard]] bool idle(std::size_t in_flight) const {
        return in_flight == 0 && status.free == depth && !status.running;
    }
};

}  // namespace

void Sender::run_queued() {
    QueueLink link;
    link.depth = m_cfg.queue_depth;
    link.status = {0, link.depth, false, false};
    std::deque<InFlight> window;
    int next_seq = 0;
    int segment = 0;
    TimePs heard_ps = now_ps();
    TimePs drained_by_ps = now_ps();  // when the moves sent should have run, by their expected durations
    TimePs resend_at_ps = -1;         // a go-back-N waiting for the line to be quiet past the FPGA's watchdog
    std::vector<std::uint8_t> last_acked;
    bool job_wait_done = false;
    qp::StatusReader reader;
    std::optional<OutgoingPacket> pending = m_motion.next();

    const auto go_back = [&] {
        if (resend_at_ps < 0) resend_at_ps = now_ps() + m_cfg.check.retry_delay_ps;
    };
    for (;;) {
        stall_if_due();
        while (m_port.in_waiting() > 0) {
            const std::uint8_t byte = *m_port.read_byte();
            if (byte == kHaltByte) {
                on_halt(window.empty() ? segment : window.front().sent.segment);
                break;
            }
            bool stray = false;
            const std::optional<qp::Status> s = reader.feed(byte, stray);
            if (stray) ++m_stray_bytes;
            if (!s) continue;
            const int front_seq = (next_seq - static_cast<int>(window.size()) + qp::kSeqModulo) % qp::kSeqModulo;
            const int acked = qp::seq_distance(front_seq, s->next_seq);
            if (acked > static_cast<int>(window.size()) || s->free > link.depth) {
                ++m_bad_statuses;  // a status hit on the wire
                continue;
            }
            for (int k = 0; k < acked; ++k) {
                window.front().sent.t_ack_ps = now_ps();
                m_sent.push_back(window.front().sent);
                last_acked = std::move(window.front().bytes);
                window.pop_front();
            }
            link.status = *s;
            heard_ps = now_ps();
            if (s->refused && !window.empty()) go_back();
        }
        if (m_halted) break;
        if (resend_at_ps >= 0 && now_ps() >= resend_at_ps) {
            resend_at_ps = -1;
            if (!window.empty() && window.front().sent.resends == m_cfg.check.retries) {
                ++m_errors;
                m_aborted = true;
                m_abort_reason = fmt::format(FMT_STRING("seg {}: not queued after {} sends"), window.front().sent.segment,
                                             m_cfg.check.retries + 1);
                say("[ERROR] " + m_abort_reason + ": the link is down, aborted");
                break;
            }
            for (InFlight& f : window) {
                write(f.bytes.data(), f.bytes.size());
                f.t_last_write_ps = now_ps();
                ++f.sent.resends;
                ++m_resends;
            }
            if (!window.empty()) {
                say(fmt::format(FMT_STRING("[WARN] seg {}: sent again with the {} after it"), window.front().sent.segment,
                                window.size() - 1));
            }
            continue;
        }
        if (!pending && link.idle(window.size())) break;
        const bool job_wait_due = pending && pending->wait_before_s > 0.0 && !job_wait_done;
        if (job_wait_due && link.idle(window.size())) {
            wait_ps(s_to_ps(pending->wait_before_s));
            job_wait_done = true;
            continue;
        }
        const bool room = static_cast<int>(window.size()) < link.depth &&
                          qp::seq_distance(link.status.next_seq, next_seq) < link.status.free;
        if (pending && !job_wait_due && resend_at_ps < 0 && room) {
            wait_ps(m_cfg.packet_processing_ps);
            InFlight f{numbered_packet(*pending, next_seq), {++segment, now_ps(), s_to_ps(pending->wait_before_s)}, 0};
            write(f.bytes.data(), f.bytes.size());
            f.t_last_write_ps = now_ps();
            drained_by_ps = std::max(drained_by_ps, now_ps()) + pending->expected_run_ps;
            window.push_back(std::move(f));
            next_seq = (next_seq + 1) % qp::kSeqModulo;
            pending = m_motion.next();
            job_wait_done = false;
            continue;
        }
        // Nothing to send now: a status, the resend's time, or a silence too long.
        TimePs deadline = resend_at_ps;
        if (deadline < 0 && !window.empty()) deadline = window.front().t_last_write_ps + m_cfg.check.retry_delay_ps;
        if (deadline < 0) deadline = std::max(heard_ps, drained_by_ps) + m_cfg.check.retry_delay_ps;
        const TimePs now = now_ps();
        if (now < deadline) {
            sc_core::wait(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(deadline - now)), m_port.data_event());
            continue;
        }
        if (resend_at_ps >= 0) continue;
        if (!window.empty()) {
            go_back();  // the packet or its status was lost
            continue;
        }
        // Waiting for room or for the end with no status for too long (one lost): the last packet queued, sent
        // again, is answered with the status and not queued twice.
        ++m_polls;
        write(last_acked.data(), last_acked.size());
        heard_ps = now_ps();
    }
    if (!m_aborted) wait_ps(s_to_ps(m_motion.wait_after_last_s()));
    m_finished = true;
    m_t_end = now_ps();
}

}  // namespace cnc::host
