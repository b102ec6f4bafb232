#include "fpga/spi/spi_slave.hpp"

#include <stdexcept>
#include <string>

namespace cnc::fpga {

SpiSlave::SpiSlave(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg, std::size_t n_axes)
    : sc_module(name),
      sclk("sclk"),
      mosi("mosi"),
      ss("ss"),
      miso("miso"),
      fifo("fifo"),
      counters("counters"),
      m_axes(n_axes),
      m_clock(clock_grid(cfg)),
      m_writer("writer") {
    SC_HAS_PROCESS(SpiSlave);
    miso.initialize(false);    // not selected: MISO low
    SC_METHOD(on_pin_change);  // also at time 0, so that pins bound to non-reset levels are sampled at edge 1
    sensitive << sclk << mosi << ss;
    SC_METHOD(on_sample);
    sensitive << m_sample;
    dont_initialize();
}

void SpiSlave::end_of_elaboration() {
    if (static_cast<std::size_t>(counters.size()) != m_axes)
        throw std::logic_error(std::string(name()) + ": bind one step counter per axis");
}

std::uint64_t SpiSlave::activations() const {
    return m_activations + m_writer.activations();
}

void SpiSlave::on_pin_change() {
    ++m_activations;
    // All changes before an edge are captured together by that edge; a pending notification is for the same
    // edge (a change at the edge's own time is seen by the next one, after that edge's sample has run).
    const TimePs now = now_ps();
    m_sample.notify(ps(m_clock.at(m_clock.first_after(now)) - now));
}

void SpiSlave::on_sample() {
    ++m_activations;
    // Timed wake, first delta of the edge: the pins still show their levels from before the edge.
    m_events.clear();
    m_core.sample(m_clock.last_at_or_before(now_ps()), ss.read(), sclk.read(), mosi.read(), m_events);
    for (const SlaveEvent& e : m_events) act(e, true);
}

void SpiSlave::select(TimePs t_ss_fall_ps) {
    const SlaveEvent e = m_core.select(m_clock.first_after(t_ss_fall_ps));
    m_select_edge = e.edge;
    act(e, false);
}

void SpiSlave::deselect(TimePs t_ss_rise_ps, const std::vector<std::uint8_t>& mosi_bytes,
                        std::vector<std::uint8_t>& miso_bytes) {
    if (m_reply_edge != m_select_edge)
        throw std::logic_error(std::string(name()) + ": SS was low too briefly for the reply to be loaded");
    miso_bytes.assign(mosi_bytes.size(), 0);
    for (std::size_t k = 0; k < 8 * mosi_bytes.size(); ++k) {
        if (reply_bit(k)) miso_bytes[k / 8] = static_cast<std::uint8_t>(miso_bytes[k / 8] | (0x80U >> (k % 8)));
    }
    act(m_core.deselect(m_clock.first_after(t_ss_rise_ps), mosi_bytes), false);
}

void SpiSlave::act(const SlaveEvent& e, bool wires) {
    switch (e.kind) {
        case SlaveEvent::Kind::FrameStart:
            m_writer.at(m_clock.at(e.edge), [this, edge = e.edge, wires] { frame_start(edge, wires); });
            break;
        case SlaveEvent::Kind::MisoShift:
            m_writer.at(m_clock.at(e.edge), [this, k = e.miso_bit] { miso.write(reply_bit(k)); });
            break;
        case SlaveEvent::Kind::FrameEnd:
            m_writer.at(m_clock.at(e.edge), [this, e, wires] { frame_end(e, wires); });
            break;
    }
}

bool SpiSlave::reply_bit(std::size_t k) const {
    return k / 8 < m_reply.size() && ((m_reply[k / 8] >> (7 - k % 8)) & 1U) != 0;  // zeros past the reply
}

void SpiSlave::frame_start(std::int64_t edge, bool wires) {
    const FifoStatus fs = fifo->status_at(edge);
    spi::Feedback fb;
    fb.status.fifo_level = fs.level;
    fb.status.fifo_full = fs.full;
    fb.status.dropped = fs.drops_before > m_drops_reported;
    fb.status.rejected = m_rejected > m_rejected_reported;
    m_drops_reported = fs.drops_before;
    m_rejected_reported = m_rejected;
    for (std::size_t i = 0; i < m_axes; ++i) fb.counts.push_back(counters[static_cast<int>(i)]->value_at_edge(edge));
    m_reply = spi::encode_feedback(fb);
    m_reply_edge = edge;
    SlaveFrameRecord& r = m_keep_frame_log ? m_frames.emplace_back() : (m_frame = SlaveFrameRecord{});
    r.seq = m_frame_count++;
    r.t_snapshot_ps = m_clock.at(edge);
    if (m_keep_frame_log) r.reply = m_reply;
    if (wires) miso.write(reply_bit(0));
}

void SpiSlave::frame_end(const SlaveEvent& e, bool wires) {
    if (wires) miso.write(false);
    SlaveFrameRecord& r = m_keep_frame_log ? m_frames.back() : m_frame;
    r.t_end_ps = m_clock.at(e.edge);
    r.mosi_bits = e.mosi_bits;
    const auto command = e.mosi_bits == spi::frame_bits(m_axes) ? spi::decode_command(e.mosi, m_axes) : std::nullopt;
    if (!command) {
        ++m_rejected;
        return;
    }
    r.accepted = true;
    ++m_accepted_count;
    r.dropped = !fifo->push(e.edge, r.seq, *command);
}

}  // namespace cnc::fpga
