#include "host/sender.hpp"
#include "common/sc_time.hpp"

#include <cstdio>

#include <fmt/format.h>

#include "host/core/packet_codec.hpp"

namespace cnc::host {

Sender::Sender(const sc_core::sc_module_name& name, const SenderConfig& cfg, uart::Cp2102& port,
               std::vector<std::uint8_t> init_packet, PacketSource& motion_packets)
    : sc_module(name),
      m_cfg(cfg),
      m_port(port),
      m_init(std::move(init_packet)),
      m_motion(motion_packets),
      m_stall(cfg.stall) {
    SC_HAS_PROCESS(Sender);
    SC_THREAD(run);
}

namespace {

// From the end of a move to the host reading its ACK: the ACK byte, USB frames and driver latency take a few ms
// (4.4 ms per gap on the 20 mm square, README); 0.1 s tells a move that overran from a byte that was lost.
constexpr TimePs kAckPathAllowancePs = 100 * kPsPerMs;

// Names the late move so that the fix is obvious: send_steps.py's fixed timeout against a long move, or a lost
// packet or ACK (framing errors, a busy step_gen), which no timeout fixes.
std::string ack_timeout_text(int segment, const OutgoingPacket& packet, TimePs timeout_ps) {
    const std::string line = packet.gcode_line > 0 ? "G-code line " + std::to_string(packet.gcode_line) + ", " : "";
    const std::string text = "seg " + std::to_string(segment) + " (" + line +
                             fmt::format(FMT_STRING("a {:.2f} s move): no ACK within {:.1f} s"),
                                         ps_to_s(packet.expected_run_ps), ps_to_s(timeout_ps));
    if (packet.expected_run_ps + kAckPathAllowancePs >= timeout_ps) {
        return text + "; raise host.ack_timeout_s above the longest move";
    }
    return text +
           ", long after the move should have ended: the packet or its ACK was lost (see the warnings), "
           "host.ack_timeout_s is long enough";
}

}  // namespace

void Sender::say(const std::string& text) {
    m_messages.push_back({now_ps(), text});
}

void Sender::on_halt(int segment) {
    m_halted = true;
    m_aborted = true;
    m_abort_reason = "seg " + std::to_string(segment) + ": the FPGA halted on its e-stop input";
    say(fmt::format(FMT_STRING("[ERROR] {} (0x{:02X}): aborted"), m_abort_reason, kHaltByte));
}

void Sender::stall_if_due() {
    if (const TimePs wait = m_stall.wait_at(now_ps())) wait_ps(wait);
}

void Sender::write(const std::uint8_t* data, std::size_t n) {
    stall_if_due();
    wait_ps(m_cfg.write_latency_ps);
    m_port.usb_write(data, n);
}

Sender::Reply Sender::wait_for_reply(int segment, TimePs deadline) {
    for (;;) {
        stall_if_due();
        while (m_port.in_waiting() > 0) {
            const std::uint8_t b = *m_port.read_byte();
            if (b == kAckByte) return Reply::Ack;
            if (b == kHaltByte) return Reply::Halt;
            if (m_cfg.check.crc && b == kNakByte) return Reply::Nak;
            char text[64];
            std::snprintf(text, sizeof text, "[WARN] seg %d: unexpected byte 0x%02X", segment, b);
            say(text);
        }
        const TimePs now = now_ps();
        if (now >= deadline) return Reply::None;
        sc_core::wait(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(deadline - now)), m_port.data_event());
    }
}

void Sender::send_init() {
    const std::vector<std::uint8_t> bytes = m_cfg.check.crc ? with_crc(m_init.data(), m_init.size()) : m_init;
    for (int send = 0;; ++send) {
        write(bytes.data(), bytes.size());
        if (!m_cfg.check.crc) {
            wait_ps(m_cfg.init_gap_ps);
            return;
        }
        const TimePs gap_end = now_ps() + m_cfg.init_gap_ps;
        const Reply reply = wait_for_reply(0, gap_end);
        if (reply != Reply::Nak || send == m_cfg.check.retries) {
            wait_ps(gap_end - now_ps());
            return;
        }
        ++m_naks;
        ++m_resends;
        say("[WARN] init packet: NAK, sent again");
        wait_ps(m_cfg.check.retry_delay_ps);
    }
}

bool Sender::send_motion(const OutgoingPacket& packet, SentPacket& sent) {
    std::vector<std::uint8_t> bytes = motion_frame(packet.bytes, packet.laser_high);
    if (m_cfg.check.crc) {
        if (m_sequence) bytes[0] = static_cast<std::uint8_t>(bytes[0] | kSequenceBit);
        m_sequence = !m_sequence;
        bytes = with_crc(bytes.data(), bytes.size());
    }
    for (;;) {
        write(bytes.data(), bytes.size());
        const Reply reply = wait_for_reply(sent.segment, now_ps() + m_cfg.ack_timeout_ps);
        if (reply == Reply::Ack) return true;
        if (reply == Reply::Halt) {
            on_halt(sent.segment);
            return false;
        }
        if (!m_cfg.check.crc || sent.resends == m_cfg.check.retries) return false;
        // A NAK, or no reply: the packet or its ACK was hit on the way. Sent again, unchanged: a move that ran and
        // lost its ACK is ACKed again by the FPGA without running twice (its sequence bit).
        if (reply == Reply::Nak) ++m_naks;
        ++sent.resends;
        ++m_resends;
        say(fmt::format(FMT_STRING("[WARN] seg {}: {}, sent again"), sent.segment,
                        reply == Reply::Nak ? "NAK" : "no ACK within the timeout"));
        wait_ps(m_cfg.check.retry_delay_ps);
    }
}

void Sender::run() {
    wait_ps(m_cfg.settle_ps);
    m_port.reset_input_buffer();
    m_t_init_write = now_ps();
    send_init();
    m_port.reset_input_buffer();
    if (m_cfg.queue_depth > 0) {
        run_queued();
        return;
    }

    int segment = 0;
    while (const std::optional<OutgoingPacket> packet = m_motion.next()) {
        ++segment;
        const TimePs job_wait_ps = s_to_ps(packet->wait_before_s);
        wait_ps(job_wait_ps);
        wait_ps(m_cfg.packet_processing_ps);
        SentPacket sent{segment, now_ps(), job_wait_ps, -1, false, 0};
        if (send_motion(*packet, sent)) {
            sent.t_ack_ps = now_ps();
            m_sent.push_back(sent);
            continue;
        }
        if (m_halted) {
            m_sent.push_back(sent);
            break;
        }
        sent.timed_out = true;
        m_sent.push_back(sent);
        ++m_errors;
        const std::string timeout = ack_timeout_text(segment, *packet, m_cfg.ack_timeout_ps);
        say("[ERROR] " + timeout);
        if (!m_cfg.continue_on_timeout) {
            say("Continue anyway? [y/N] N: aborted");
            m_aborted = true;
            m_abort_reason = timeout;
            break;
        }
    }
    if (!m_aborted) wait_ps(s_to_ps(m_motion.wait_after_last_s()));
    m_finished = true;
    m_t_end = now_ps();
}

}  // namespace cnc::host
