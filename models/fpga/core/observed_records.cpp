#include "fpga/core/observed_records.hpp"

#include <algorithm>

#include "fpga/core/step_schedule.hpp"

namespace cnc::fpga {

namespace {

// uart_rx.v's and step_gen.v's state codes.
constexpr std::uint8_t kUartRxIdle = 0, kUartRxStop = 3;
constexpr std::uint8_t kIdle = 0, kDirWait = 2, kRun = 3, kHalted = 5;

}  // namespace

void ObservedRecords::settle_ack(std::int64_t n, const FpgaNets& now) {
    if (m_ack_edge < 0 || n < m_ack_edge) return;
    // top.v: tx_start is high at the edge after busy fell, unless uart_tx was busy (the ACK is dropped). It may have
    // been high at the edge before too, for a NAK (with the packet check): tx_nak changes then, so that edge is seen.
    if (n == m_ack_edge && now.tx_start) {
        ++m_stats.acks_sent;
        if (m_ack_packet >= m_packets.first() && m_ack_packet < m_packets.size()) {
            m_packets[m_ack_packet].record.t_ack_start_ps = m_clock.at(n);
        }
    } else {
        ++m_stats.acks_dropped;
    }
    m_ack_edge = -1;
}

PacketRecord* ObservedRecords::running() {
    if (m_running < m_packets.first() || m_running >= m_packets.size()) return nullptr;
    return &m_packets[m_running].record;
}

void ObservedRecords::edge(std::int64_t n, const FpgaNets& now) {
    if (m_from_nets) {
        from_inner_nets(n, now);
    } else {
        from_pins(n, now);
    }
    while (m_final < m_packets.size() && m_packets[m_final].final) ++m_final;
    m_prev = now;
}

void ObservedRecords::from_pins(std::int64_t n, const FpgaNets& now) {
    if (now.busy && !m_prev.busy) {
        PacketRecord r;
        r.t_pkt_valid_ps = m_clock.at(std::max<std::int64_t>(n - 1, 0));
        r.accepted = true;
        m_running = m_packets.size();
        m_packets.push_back({r, true});
    }
    if (m_prev.busy && !now.busy) {
        if (PacketRecord* r = running()) r->t_busy_fall_ps = m_clock.at(n);
        m_ack_packet = m_running;
        m_ack_awaited = m_cfg.queue_depth == 0;  // the queue's statuses are no ACKs
    }
    if (m_prev.tx && !now.tx && m_ack_awaited) {
        ++m_stats.acks_sent;
        if (m_ack_packet >= m_packets.first() && m_ack_packet < m_packets.size()) {
            m_packets[m_ack_packet].record.t_ack_start_ps = m_clock.at(n);
        }
        m_ack_awaited = false;
    }
}

void ObservedRecords::from_inner_nets(std::int64_t n, const FpgaNets& now) {
    const TimePs t = m_clock.at(n);
    settle_ack(n, now);
    if (now.rx_valid && !m_prev.rx_valid) ++m_stats.bytes_received;
    if (m_prev.uart_rx_state == kUartRxStop && now.uart_rx_state == kUartRxIdle && !now.rx_valid) {
        ++m_stats.framing_errors;  // a low stop bit: the byte is dropped
    }
    // A packet that ends clears timeout_active too, with one of the decoder's strobes.
    if (m_prev.timeout_active && !now.timeout_active && !now.decoder_pkt_valid && !now.cfg_valid && !now.crc_error &&
        !now.pkt_repeat) {
        ++m_stats.watchdog_resets;
    }
    if (now.crc_error && !m_prev.crc_error) ++m_stats.crc_errors;
    if (now.pkt_repeat && !m_prev.pkt_repeat) ++m_stats.repeats;
    if (now.tx_start && now.tx_nak && !(m_prev.tx_start && m_prev.tx_nak)) ++m_stats.naks_sent;
    if (now.queued && !m_prev.queued) ++m_stats.queued;
    if (now.again && !m_prev.again) ++m_stats.answered_again;
    if (now.refused && !m_prev.refused) ++m_stats.refused;
    if (now.status_start && !m_prev.status_start) ++m_stats.statuses_sent;
    // What step_gen sees at the next edge: IDLE, and no halt.
    const bool takes = now.step_gen_state == kIdle && !now.halt;
    if (now.cfg_valid && !m_prev.cfg_valid) {
        m_inits.push_back({t, now.numerator_x, now.numerator_y, m_cfg.init_packet_wired && takes});
    }
    // Before a packet of this edge: the packet queue hands step_gen its next move at the edge busy falls.
    if (m_prev.busy && !now.busy) {
        if (PacketRecord* r = running()) r->t_busy_fall_ps = t;
        if (!now.halt && m_cfg.queue_depth == 0) {  // halt high at the next edge: no ACK; the queue's status instead
            m_ack_edge = n + 1;
            m_ack_packet = m_running;
        }
    }
    if (now.pkt_valid && !m_prev.pkt_valid) {
        PacketRecord r;
        r.t_pkt_valid_ps = t;
        r.motion = now.motion;
        r.steps_x = now.steps_x;
        r.steps_y = now.steps_y;
        r.feed = now.feed_rate;
        r.accepted = takes;
        if (r.accepted) {
            r.period_overflow = compute_periods(abs_steps(r.steps_x), abs_steps(r.steps_y), r.feed, now.num_x,
                                                now.num_y, m_cfg)
                                    .overflow;
            m_running = m_packets.size();
        }
        m_packets.push_back({r, !r.accepted});
    }
    if (now.halted && !m_prev.halted) {
        m_stats.halted_at_ps = t;
        // A move halted before DIR_WAIT ended: its periods are the ones step_gen would have set.
        PacketRecord* r = running();
        if (r != nullptr && !m_packets[m_running].final) {
            const StepPeriods p =
                compute_periods(abs_steps(r->steps_x), abs_steps(r->steps_y), r->feed, now.num_x, now.num_y, m_cfg);
            r->period_x_cycles = p.x_cycles;
            r->period_y_cycles = p.y_cycles;
            m_packets[m_running].final = true;
        }
    } else if (m_prev.step_gen_state == kDirWait && now.step_gen_state != kDirWait) {
        if (PacketRecord* r = running()) {
            r->period_x_cycles = now.period_x;
            r->period_y_cycles = now.period_y;
            if (now.step_gen_state == kRun) r->t_run_start_ps = m_clock.at(n + 1);  // its first RUN cycle
            m_packets[m_running].final = true;
        }
    }
}

}  // namespace cnc::fpga
