#include "fpga/top.hpp"

#include "common/link_bytes.hpp"

#include <algorithm>
#include <iterator>

namespace cnc::fpga {

Top::Top(const sc_core::sc_module_name& name, const FpgaConfig& cfg)
    : Board(name),
      m_cfg((validate(cfg), cfg)),
      m_clock(clock_grid(cfg)),
      m_numerator_x("numerator_x", cfg.numerator_default),
      m_numerator_y("numerator_y", cfg.numerator_default),
      m_ramp_accel("ramp_accel", cfg.ramp_accel_default),
      m_ramp_start("ramp_start", cfg.ramp_start_default),
      m_ramp_jerk("ramp_jerk", cfg.ramp_jerk_default),
      uart_rx_inst("uart_rx_inst", cfg),
      pkt_dec_inst("pkt_dec_inst", cfg),
      step_gen_inst("step_gen_inst", cfg),
      laser_ctrl_inst("laser_ctrl_inst", cfg),
      uart_tx_inst("uart_tx_inst", cfg),
      m_writer("writer") {
    SC_HAS_PROCESS(Top);

    uart_rx_inst.rx(rx);
    uart_rx_inst.rx_data(m_rx_data);
    uart_rx_inst.rx_valid(rx_valid);

    pkt_dec_inst.rx_data(m_rx_data);
    pkt_dec_inst.rx_valid(rx_valid);
    pkt_dec_inst.motion(m_motion);
    pkt_dec_inst.steps_x(m_steps_x);
    pkt_dec_inst.steps_y(m_steps_y);
    pkt_dec_inst.feed_rate(m_feed_rate);
    pkt_dec_inst.laser_high(m_laser_high);
    pkt_dec_inst.seq(m_seq);
    pkt_dec_inst.numerator_x(m_numerator_x);
    pkt_dec_inst.numerator_y(m_numerator_y);
    pkt_dec_inst.ramp_accel(m_ramp_accel);
    pkt_dec_inst.ramp_start(m_ramp_start);
    pkt_dec_inst.ramp_jerk(m_ramp_jerk);
    pkt_dec_inst.cfg_valid(cfg_valid);
    pkt_dec_inst.crc_error(m_crc_error);
    pkt_dec_inst.repeat(m_repeat);

    if (cfg.queue_depth > 0) {
        wire_queue(cfg);
    } else {
        pkt_dec_inst.pkt_valid(pkt_valid);
        step_gen_inst.steps_x(m_steps_x);
        step_gen_inst.steps_y(m_steps_y);
        step_gen_inst.feed_rate(m_feed_rate);
        step_gen_inst.pkt_valid(pkt_valid);
        laser_ctrl_inst.motion(m_motion);
        laser_ctrl_inst.laser_high(m_laser_high);
        laser_ctrl_inst.pkt_valid(pkt_valid);
    }
    if (cfg.init_packet_wired) {  // §5.2.6: "must also be driven" to step_gen
        step_gen_inst.numerator_x(m_numerator_x);
        step_gen_inst.numerator_y(m_numerator_y);
        step_gen_inst.ramp_accel(m_ramp_accel);
        step_gen_inst.ramp_start(m_ramp_start);
        step_gen_inst.ramp_jerk(m_ramp_jerk);
        step_gen_inst.cfg_valid(cfg_valid);
    } else {
        step_gen_inst.numerator_x(m_numerator_unconnected);
        step_gen_inst.numerator_y(m_numerator_unconnected);
        step_gen_inst.ramp_accel(m_numerator_unconnected);
        step_gen_inst.ramp_start(m_numerator_unconnected);
        step_gen_inst.ramp_jerk(m_numerator_unconnected);
        step_gen_inst.cfg_valid(m_cfg_valid_unconnected);
    }
    step_gen_inst.dir_x(dir_x);
    step_gen_inst.step_x(step_x);
    step_gen_inst.dir_y(dir_y);
    step_gen_inst.step_y(step_y);
    step_gen_inst.busy(busy);

    laser_ctrl_inst.busy(busy);
    laser_ctrl_inst.inhibit(m_laser_inhibit);
    laser_ctrl_inst.laser(laser);

    uart_tx_inst.tx_data(m_tx_data);
    uart_tx_inst.tx_start(tx_start);
    uart_tx_inst.tx_busy(m_tx_busy);
    uart_tx_inst.tx(tx);

    SC_METHOD(on_busy);
    sensitive << busy;
    dont_initialize();
    SC_METHOD(on_cfg_valid);
    sensitive << cfg_valid;
    dont_initialize();
    SC_METHOD(on_crc_error);
    sensitive << m_crc_error;
    dont_initialize();
    SC_METHOD(on_repeat);
    sensitive << m_repeat;
    dont_initialize();
    if (cfg.queue_depth > 0) {
        SC_METHOD(on_status_req);
        sensitive << m_status_req;
        dont_initialize();
    }
    if (cfg.queue_depth > 0 || cfg.estop_input) {
        SC_METHOD(on_tx_busy);
        sensitive << m_tx_busy;
        dont_initialize();
    }
    if (cfg.estop_input) {
        SC_METHOD(on_estop);
        sensitive << estop;
        dont_initialize();
    }
    if (cfg.interlock_input) {
        SC_METHOD(on_lid);
        sensitive << lid_open;
        dont_initialize();
    }
    tie_unused_inputs(cfg);
}

// An input changed now is sampled by its synchroniser's first stage at the next edge and seen one edge later.
std::int64_t Top::synchronised_edge() const {
    return m_clock.first_after(now_ps()) + 1;
}

// step_gen halts at the edge the press is seen; the halt byte starts at the edge after, or when uart_tx is free.
void Top::on_estop() {
    ++m_activations;
    if (!estop.read() || m_halted) return;
    const std::int64_t halt = synchronised_edge();
    m_halted = true;
    m_halt_edge = halt;
    m_halted_at_ps = m_clock.at(halt);
    step_gen_inst.halt_at(halt);
    if (packet_queue_inst) packet_queue_inst->halt_at(halt);
    m_halt_byte_due = true;
    // A start asked for up to the edge before the first sample has not raised tx_busy yet, but keeps uart_tx busy
    // past halt + 1 (a byte is ten bits): its fall sends the halt byte.
    const bool start_under_way = m_tx_edge >= 0 && m_tx_edge >= halt - 3;
    if (m_status_tx == StatusTx::Idle && !m_tx_busy.read() && !start_under_way) send_next_byte(halt + 1);
}

// The lid's level reaches laser_ctrl's register at the edge it is seen.
void Top::on_lid() {
    ++m_activations;
    const bool open = lid_open.read();
    m_writer.at(m_clock.at(synchronised_edge()), [this, open] { m_laser_inhibit.write(open); });
}

void Top::wire_queue(const FpgaConfig& cfg) {
    packet_queue_inst = std::make_unique<PacketQueue>("packet_queue_inst", cfg);
    PacketQueue& q = *packet_queue_inst;
    pkt_dec_inst.pkt_valid(m_decoder_pkt_valid);
    q.motion(m_motion);
    q.seq(m_seq);
    q.steps_x(m_steps_x);
    q.steps_y(m_steps_y);
    q.feed_rate(m_feed_rate);
    q.laser_high(m_laser_high);
    q.pkt_valid(m_decoder_pkt_valid);
    q.crc_error(m_crc_error);
    q.busy(busy);
    q.q_motion(m_q_motion);
    q.q_steps_x(m_q_steps_x);
    q.q_steps_y(m_q_steps_y);
    q.q_feed_rate(m_q_feed_rate);
    q.q_laser_high(m_q_laser_high);
    q.q_pkt_valid(pkt_valid);
    q.status_req(m_status_req);
    step_gen_inst.steps_x(m_q_steps_x);
    step_gen_inst.steps_y(m_q_steps_y);
    step_gen_inst.feed_rate(m_q_feed_rate);
    step_gen_inst.pkt_valid(pkt_valid);
    laser_ctrl_inst.motion(m_q_motion);
    laser_ctrl_inst.laser_high(m_q_laser_high);
    laser_ctrl_inst.pkt_valid(pkt_valid);
}

void Top::start_tx(std::int64_t edge, std::uint8_t byte) {
    if (edge == m_tx_edge) {  // the halt byte wins over an ACK, an ACK over a NAK
        if (byte == kHaltByte || (byte == kAckByte && m_tx_byte != kHaltByte)) m_tx_byte = byte;
        return;
    }
    m_tx_edge = edge;
    m_tx_byte = byte;
    m_writer.at(m_clock.at(edge), [this] {
        if (m_tx_byte == kNakByte) ++m_naks_sent;
        m_tx_data.write(m_tx_byte);
        tx_start.write(true);
    });
    m_writer.at(m_clock.at(edge + 1), [this] { tx_start.write(false); });
}

// A packet whose CRC failed: edge k+1 sees the strobe of edge k and answers NAK if uart_tx is free.
void Top::on_crc_error() {
    ++m_activations;
    if (!m_crc_error.read() || packet_queue_inst || m_halted) return;  // the queue answers with its status
    if (m_tx_busy.read()) return;
    start_tx(m_clock.last_at_or_before(now_ps()) + 1, kNakByte);
}

// A move sent again (the host lost its ACK): ACKed at once if it has run and nothing runs now; a move still running
// is ACKed when busy falls.
void Top::on_repeat() {
    ++m_activations;
    if (!m_repeat.read() || m_halted) return;
    if (busy.read() || m_tx_busy.read()) return;
    start_tx(m_clock.last_at_or_before(now_ps()) + 1, kAckByte);
}

void Top::on_busy() {
    ++m_activations;
    if (busy.read() || m_halted) return;
    // busy fell at edge f: edge f+1 sees busy_prev && !busy and samples tx_busy as it was after edge f.
    const std::int64_t f = m_clock.last_at_or_before(now_ps());
    const TimePs t_start = m_clock.at(f + 1);
    ++m_pkt_count;
    if (packet_queue_inst) return;  // the queue's status says the move ended
    if (m_tx_busy.read()) {  // no pending flag: the ACK is lost (seed 000 §4.13)
        ++m_acks_dropped;
        m_acks.push_back({m_clock.at(f), -1});
        return;
    }
    ++m_acks_sent;
    m_acks.push_back({m_clock.at(f), t_start});
    start_tx(f + 1, kAckByte);
}

void Top::on_status_req() {
    ++m_activations;
    if (!m_status_req.read()) return;
    m_status_due = true;
    if (m_status_tx == StatusTx::Idle && !m_tx_busy.read() && !m_halted) {
        start_status(m_clock.last_at_or_before(now_ps()) + 1);
    }
}

void Top::start_status(std::int64_t edge) {
    const auto bytes = queue_protocol::encode(packet_queue_inst->take_status());
    m_status_due = false;
    m_status_tx = StatusTx::Byte0;
    m_status_byte1 = bytes[1];
    ++m_statuses_sent;
    start_tx(edge, bytes[0]);
}

// uart_tx's busy fell at edge g: IDLE at g+1 takes the next byte.
void Top::on_tx_busy() {
    ++m_activations;
    if (m_tx_busy.read()) return;
    send_next_byte(m_clock.last_at_or_before(now_ps()) + 1);
}

void Top::send_next_byte(std::int64_t edge) {
    if (m_status_tx == StatusTx::Byte0) {
        m_status_tx = StatusTx::Byte1;
        start_tx(edge, m_status_byte1);
        return;
    }
    m_status_tx = StatusTx::Idle;
    if (m_halt_byte_due) {
        m_halt_byte_due = false;
        start_tx(std::max(edge, m_halt_edge + 1), kHaltByte);  // top.v: once halted is high
        return;
    }
    if (m_status_due && !m_halted) start_status(edge);
}

void Top::on_cfg_valid() {
    ++m_activations;
    if (!cfg_valid.read()) return;
    const std::int64_t k = m_clock.last_at_or_before(now_ps());
    m_inits.push_back({m_clock.at(k), m_numerator_x.read(), m_numerator_y.read(),
                       m_cfg.init_packet_wired && step_gen_inst.idle_at_edge(k + 1)});
}

const RecordLog<PacketDecoder::MotionOut>& Top::handed_over() const {
    return packet_queue_inst ? packet_queue_inst->issued() : pkt_dec_inst.motions();
}

std::vector<PacketRecord> Top::packets() const {
    std::vector<PacketRecord> out;
    for (std::size_t i = step_gen_inst.moves().first(); i < packet_count(); ++i) out.push_back(packet(i));
    return out;
}

void Top::drop_packets_before(std::size_t end) {
    const auto& moves = step_gen_inst.moves();
    // A dropped move's ACK is the one at its busy fall; a later move's busy falls later.
    TimePs last_busy_fall_ps = -1;
    for (std::size_t i = moves.first(); i < end && i < moves.size(); ++i) {
        if (moves[i].accepted) last_busy_fall_ps = moves[i].t_busy_fall_ps;
    }
    const auto kept = std::partition_point(
        m_acks.begin(), m_acks.end(), [&](const AckAfterBusy& a) { return a.t_busy_fall_ps <= last_busy_fall_ps; });
    m_acks.drop_before(m_acks.first() + static_cast<std::size_t>(std::distance(m_acks.begin(), kept)));
    if (packet_queue_inst) {
        packet_queue_inst->drop_issued_before(end);
        pkt_dec_inst.drop_motions_before(pkt_dec_inst.motions().size());
    } else {
        pkt_dec_inst.drop_motions_before(end);
    }
    step_gen_inst.drop_moves_before(end);
}

PacketRecord Top::packet(std::size_t i) const {
    // The decoder logs a packet when it schedules pkt_valid, step_gen when pkt_valid is high: a run stopped in
    // between has one decoder entry more, which is left out until step_gen has seen it.
    const auto& m = handed_over()[i];
    const auto& s = step_gen_inst.moves()[i];
    PacketRecord r;
    r.t_pkt_valid_ps = m.t_pkt_valid_ps;
    r.motion = m.fields.motion;
    r.steps_x = m.fields.steps_x;
    r.steps_y = m.fields.steps_y;
    r.feed = m.fields.feed;
    r.accepted = s.accepted;
    r.period_x_cycles = s.periods.x_cycles;
    r.period_y_cycles = s.periods.y_cycles;
    r.period_overflow = s.periods.overflow;
    r.t_run_start_ps = s.t_run_start_ps;
    r.t_busy_fall_ps = s.t_busy_fall_ps;
    const auto ack = std::lower_bound(m_acks.begin(), m_acks.end(), s.t_busy_fall_ps,
                                      [](const AckAfterBusy& a, TimePs t) { return a.t_busy_fall_ps < t; });
    if (s.accepted && ack != m_acks.end() && ack->t_busy_fall_ps == s.t_busy_fall_ps) {
        r.t_ack_start_ps = ack->t_ack_start_ps;
    }
    return r;
}

FpgaStats Top::stats() const {
    FpgaStats s;
    s.bytes_received = uart_rx_inst.bytes_received();
    s.framing_errors = uart_rx_inst.framing_errors();
    s.watchdog_resets = pkt_dec_inst.watchdog_resets();
    s.acks_sent = m_acks_sent;
    s.acks_dropped = m_acks_dropped;
    s.crc_errors = pkt_dec_inst.crc_errors();
    s.naks_sent = m_naks_sent;
    s.repeats = pkt_dec_inst.repeats();
    s.halted_at_ps = m_halted_at_ps;
    if (packet_queue_inst) {
        const PacketQueueCore& q = packet_queue_inst->core();
        s.queued = q.queued();
        s.answered_again = q.answered_again();
        s.refused = q.refused();
        s.statuses_sent = m_statuses_sent;
    }
    return s;
}

std::uint64_t Top::activations() const {
    return m_activations + m_writer.activations() + uart_rx_inst.activations() + pkt_dec_inst.activations() +
           step_gen_inst.activations() + laser_ctrl_inst.activations() + uart_tx_inst.activations() +
           (packet_queue_inst ? packet_queue_inst->activations() : 0);
}

void Top::add_traces(sc_core::sc_trace_file* tf) const {
    sc_core::sc_trace(tf, m_rx_data, m_rx_data.name());
    sc_core::sc_trace(tf, m_motion, m_motion.name());
    sc_core::sc_trace(tf, m_steps_x, m_steps_x.name());
    sc_core::sc_trace(tf, m_steps_y, m_steps_y.name());
    sc_core::sc_trace(tf, m_feed_rate, m_feed_rate.name());
    sc_core::sc_trace(tf, m_numerator_x, m_numerator_x.name());
    sc_core::sc_trace(tf, m_numerator_y, m_numerator_y.name());
    if (m_cfg.ramp != StepRamp::None) {
        sc_core::sc_trace(tf, m_ramp_accel, m_ramp_accel.name());
        sc_core::sc_trace(tf, m_ramp_start, m_ramp_start.name());
        if (m_cfg.ramp == StepRamp::SCurve) sc_core::sc_trace(tf, m_ramp_jerk, m_ramp_jerk.name());
    }
    sc_core::sc_trace(tf, m_tx_busy, m_tx_busy.name());
    laser_ctrl_inst.add_traces(tf);
    if (m_cfg.interlock_input) sc_core::sc_trace(tf, m_laser_inhibit, m_laser_inhibit.name());
}

}  // namespace cnc::fpga
