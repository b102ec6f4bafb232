// The Python sender of seed 000 appendix A.2 (send_steps.py) with a host timing model: open the port, settle,
// flush, send the init packet, then one motion packet at a time, each followed by a wait for the ACK 0xAA
// (stop-and-wait) with a timeout. The script's time goes into documented parameters (processing, OS write
// latency); the USB and UART timing belongs to the CP2102 model it writes through.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <systemc>

#include "common/record_log.hpp"
#include "common/units.hpp"
#include "host/core/sender_config.hpp"
#include "uart/cp2102.hpp"

namespace cnc::host {

// A motion packet and what the host knows about it, so that its messages can say which move is late.
struct OutgoingPacket {
    std::array<std::uint8_t, 11> bytes{};  // seed 000 T3.6: 11-byte motion packet
    int gcode_line = 0;                    // source line of the move (0: unknown, e.g. a steps-file row without it)
    TimePs expected_run_ps = 0;            // how long step_gen should run it (dominant steps x NUMERATOR / feed)
    double wait_before_s = 0.0;            // the job's host wait before it (dwell, pause, Z move)
    std::optional<std::uint16_t> laser_high;  // with fpga.laser_pwm: the PWM high time sent after FeedRate
};

// The motion packets in order, made as the sender asks for them, so that a long job is never held whole.
class PacketSource {
public:
    virtual ~PacketSource() = default;
    // The next packet; none after the last.
    [[nodiscard]] virtual std::optional<OutgoingPacket> next() = 0;
    // The job's host wait after the last packet (asked once next() has returned none).
    [[nodiscard]] virtual double wait_after_last_s() = 0;
};

struct SentPacket {
    int segment = 0;            // 1-based, as the script counts
    TimePs t_write_ps = 0;      // the script calls ser.write()
    TimePs wait_before_ps = 0;  // the job's host wait slept before it (dwell, pause, Z move)
    TimePs t_ack_ps = -1;       // the ACK was read (-1: never)
    bool timed_out = false;
    int resends = 0;  // with the packet check: sent again after a NAK or a timeout
};

struct SenderMessage {
    TimePs t_ps = 0;
    std::string text;  // as the script would print it
};

class Sender : public sc_core::sc_module {
public:
    // Takes the motion packets from `motion_packets` (which must outlive it) one at a time as it sends them. The
    // job's host waits (G4 dwells, M0 pauses, Z moves) are slept before the packet they come with (after the
    // previous ACK: the host sleeps once the machine has finished), and after the last ACK.
    Sender(const sc_core::sc_module_name& name, const SenderConfig& cfg, uart::Cp2102& port,
           std::vector<std::uint8_t> init_packet, PacketSource& motion_packets);

    // Every packet sent, numbered over the whole run (size() counts the dropped ones too).
    [[nodiscard]] const RecordLog<SentPacket>& packets() const { return m_sent; }
    // The reader has read the packets before index `end`: they go.
    void drop_packets_before(std::size_t end) { m_sent.drop_before(end); }
    [[nodiscard]] const std::vector<SenderMessage>& messages() const { return m_messages; }
    [[nodiscard]] bool finished() const { return m_finished; }
    [[nodiscard]] bool aborted() const { return m_aborted; }
    // The FPGA sent its halt byte (its e-stop input, fpga.estop): the script stopped there.
    [[nodiscard]] bool halted() const { return m_halted; }
    // The ACK timeout that made the script stop (empty unless aborted()): the move, its line and duration.
    [[nodiscard]] const std::string& abort_reason() const { return m_abort_reason; }
    [[nodiscard]] int errors() const { return m_errors; }
    // With the packet check: packets sent again, NAKs read, and timeouts answered by a resend.
    [[nodiscard]] int resends() const { return m_resends; }
    [[nodiscard]] int naks() const { return m_naks; }
    // With the packet queue: status bytes that fit no status, statuses naming packets not in flight (both: hit on
    // the wire), and packets sent again only to have the status repeated.
    [[nodiscard]] int stray_bytes() const { return m_stray_bytes; }
    [[nodiscard]] int bad_statuses() const { return m_bad_statuses; }
    [[nodiscard]] int polls() const { return m_polls; }
    // How long the host stall (SenderConfig::stall) held the script up.
    [[nodiscard]] TimePs stalled_ps() const { return m_stall.held_ps(); }
    [[nodiscard]] TimePs t_init_write_ps() const { return m_t_init_write; }
    [[nodiscard]] TimePs t_end_ps() const { return m_t_end; }

private:
    void run();
    // With the FPGA's packet queue (sender_queue.cpp).
    void run_queued();
    void write(const std::uint8_t* data, std::size_t n);
    enum class Reply { Ack, Nak, Halt, None };
    // Waits for 0xAA (or, with the packet check, a NAK) until `deadline`. Other bytes are reported and skipped (the
    // script's loop).
    Reply wait_for_reply(int segment, TimePs deadline);
    // The init packet; with the packet check sent again while the FPGA answers NAK within the init gap.
    void send_init();
    // Writes a motion packet (framed with the packet check) until its ACK, a NAK or a timeout past the retries.
    // Returns whether the ACK came.
    bool send_motion(const OutgoingPacket& packet, SentPacket& sent);
    void say(const std::string& text);
    // Inside the stall: waits for its end.
    void stall_if_due();
    // The halt byte read: the script stops.
    void on_halt(int segment);

    const SenderConfig m_cfg;
    uart::Cp2102& m_port;
    const std::vector<std::uint8_t> m_init;  // the init packet, without its CRC
    PacketSource& m_motion;
    RecordLog<SentPacket> m_sent;
    std::vector<SenderMessage> m_messages;
    TimePs m_t_init_write = -1;
    TimePs m_t_end = -1;
    int m_errors = 0;
    int m_resends = 0;
    int m_naks = 0;
    int m_stray_bytes = 0;
    int m_bad_statuses = 0;
    int m_polls = 0;
    HostStall m_stall;
    bool m_sequence = false;  // the packet check's alternating bit of the next new move
    bool m_finished = false;
    bool m_aborted = false;
    bool m_halted = false;
    std::string m_abort_reason;
};

}  // namespace cnc::host
