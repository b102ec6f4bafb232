// The FPGA's records (fpga_records.hpp) read off a clocked model of top.v instead of logged by the event-driven
// blocks: after each clock edge that changed one of the nets below, those nets' values. The rules are top.v's:
// step_gen takes a packet whose pkt_valid it sees in IDLE; its periods are in place when DIR_WAIT ends; busy falls
// at DONE; uart_tx starts the ACK one edge after busy falls unless it is still sending. With the packet check the
// decoder's crc_error and pkt_repeat strobes and the NAKs tx_start sends are counted too. With the e-stop, step_gen
// takes nothing while top.v's halt is high, no ACK follows a busy fall it sees, and the edge halted rises is the halt.
// With the packet queue the records are the moves the queue hands step_gen, and its statuses replace the ACKs.
#pragma once
#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/clock_grid.hpp"
#include "common/record_log.hpp"
#include "fpga/core/fpga_config.hpp"
#include "fpga/core/fpga_records.hpp"

namespace cnc::fpga {

// Values after one clock edge (top.v's nets; the state codes are uart_rx.v's and step_gen.v's).
struct FpgaNets {
    bool busy = false;
    bool tx = true;  // the UART line idles high
    bool rx_valid = false;
    bool pkt_valid = false;
    bool cfg_valid = false;
    bool tx_start = false;
    bool timeout_active = false;  // packet_decoder: a packet is under way and its watchdog counts
    bool crc_error = false;       // with the packet check: packet_decoder's strobes and the byte tx_start sends
    bool pkt_repeat = false;
    bool tx_nak = false;
    bool halt = false;  // with the e-stop: top.v's halt (step_gen's input) and halted
    bool halted = false;
    // With the packet queue: pkt_valid above is the queue's to step_gen; the decoder's, and the queue's strobes (a
    // packet queued, answered again, refused) and the start of a status's first byte.
    bool decoder_pkt_valid = false;
    bool queued = false;
    bool again = false;
    bool refused = false;
    bool status_start = false;
    std::uint8_t uart_rx_state = 0;
    std::uint8_t step_gen_state = 0;
    std::uint8_t motion = 0;
    std::int32_t steps_x = 0;
    std::int32_t steps_y = 0;
    std::uint16_t feed_rate = 0;
    std::uint32_t numerator_x = 0;  // the decoder's outputs
    std::uint32_t numerator_y = 0;
    std::uint32_t num_x = 0;  // step_gen's latched numerators
    std::uint32_t num_y = 0;
    std::uint32_t period_x = 0;
    std::uint32_t period_y = 0;
};

class ObservedRecords {
public:
    // `from_nets` false: a design without top.v's inner nets (a user's top). Its records are read off its pins
    // alone: each busy pulse one accepted packet, its pkt_valid the edge before busy rose (top.v's SETUP), its ACK
    // the first start bit on tx after busy fell; fields, periods and the counters other than the ACKs stay 0.
    ObservedRecords(const FpgaConfig& cfg, const ClockGrid& clock, bool from_nets)
        : m_cfg(cfg), m_clock(clock), m_from_nets(from_nets) {}

    // The nets after edge n (n > the last edge given; the edges in between changed none of them).
    void edge(std::int64_t n, const FpgaNets& now);
    [[nodiscard]] bool from_nets() const { return m_from_nets; }

    // Records whose acceptance and periods are final, in pkt_valid order (what a reader may act on).
    [[nodiscard]] std::size_t packet_count() const { return m_final; }
    [[nodiscard]] const PacketRecord& packet(std::size_t i) const { return m_packets[i].record; }
    void drop_packets_before(std::size_t end) { m_packets.drop_before(std::min(end, m_final)); }
    [[nodiscard]] const std::vector<InitRecord>& inits() const { return m_inits; }
    [[nodiscard]] const FpgaStats& stats() const { return m_stats; }

private:
    void from_inner_nets(std::int64_t n, const FpgaNets& now);
    void from_pins(std::int64_t n, const FpgaNets& now);
    void settle_ack(std::int64_t n, const FpgaNets& now);
    [[nodiscard]] PacketRecord* running();

    struct Logged {
        PacketRecord record;
        bool final = false;  // acceptance and periods known
    };
    const FpgaConfig m_cfg;
    const ClockGrid m_clock;
    const bool m_from_nets;
    FpgaNets m_prev;  // reset values
    RecordLog<Logged> m_packets;
    std::size_t m_final = 0;
    std::size_t m_running = 0;      // the accepted packet step_gen runs (valid while busy)
    std::int64_t m_ack_edge = -1;   // the edge that starts the ACK of the busy fall before it, or -1
    std::size_t m_ack_packet = 0;
    bool m_ack_awaited = false;  // read off the pins: busy fell, its ACK's start bit not seen yet
    std::vector<InitRecord> m_inits;
    FpgaStats m_stats;
};

}  // namespace cnc::fpga
