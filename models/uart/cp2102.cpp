#include "uart/cp2102.hpp"
#include "common/sc_time.hpp"

#include <algorithm>
#include <iterator>

#include "common/bad_input.hpp"
#include "uart/core/line_receiver.hpp"

namespace cnc::uart {

namespace {

sc_core::sc_time ps(TimePs t) {
    return sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t));
}

}  // namespace

Cp2102::Cp2102(const sc_core::sc_module_name& name, const Cp2102Config& cfg)
    : sc_core::sc_module(name),
      txd("txd"),
      rxd("rxd"),
      m_cfg(cfg),
      m_baud(cp2102_baud(cfg.requested_baud, cfg.ideal_baud)),
      m_clk(m_baud.bit_clock()),
      m_out{UsbSpikeDraw(cfg.usb_spikes, cfg.usb_spike_seed, 0)},
      m_in{UsbSpikeDraw(cfg.usb_spikes, cfg.usb_spike_seed, 1)},
      m_rx_line{"rxd", true, {}} {
    validate(cfg.format);
    if (cfg.usb_frame_ps <= 0) throw BadInput("", "USB frame period must be > 0");
    if (cfg.usb_latency_ps < 0) throw BadInput("", "USB latency must be >= 0");
    SC_HAS_PROCESS(Cp2102);
    txd.initialize(true);  // idle line

    SC_METHOD(usb_out_arrival);
    sensitive << m_usb_out_ev;
    dont_initialize();

    SC_THREAD(tx_thread);

    SC_METHOD(on_rxd);
    sensitive << rxd.value_changed();
    dont_initialize();

    SC_METHOD(rx_decide);
    sensitive << m_rx_decide_ev;
    dont_initialize();

    SC_METHOD(rx_deliver);
    sensitive << m_rx_deliver_ev;
    dont_initialize();
}

void Cp2102::wait_until(TimePs t_ps) {
    const TimePs now = now_ps();
    if (t_ps > now) wait(ps(t_ps - now));
}

TimePs Cp2102::spiked(SpikedPipe& pipe, TimePs t_frame_ps, TimePs t_due_ps, std::int64_t& spikes, TimePs& delay_ps) {
    const std::int64_t frame = t_frame_ps / m_cfg.usb_frame_ps;
    const TimePs extra = pipe.draw.extra_ps(frame);
    if (extra > 0 && frame != pipe.last_frame) {
        ++spikes;
        delay_ps += extra;
    }
    pipe.last_frame = frame;
    pipe.last_ps = std::max(pipe.last_ps, t_due_ps + extra);
    return pipe.last_ps;
}

void Cp2102::usb_write(const std::uint8_t* data, std::size_t n) {
    const TimePs now = now_ps();
    const TimePs t_frame = next_frame_start(now, m_cfg.usb_frame_ps);
    const TimePs t_usb = spiked(m_out, t_frame, t_frame, m_stats.usb_spikes_out, m_stats.usb_spike_delay_out_ps);
    for (std::size_t i = 0; i < n; ++i) m_usb_out.push_back({data[i], now, t_usb});
    if (n > 0) m_usb_out_ev.notify(ps(t_usb - now));  // an earlier pending notification is kept
}

void Cp2102::usb_out_arrival() {
    const TimePs now = now_ps();
    bool arrived = false;
    while (!m_usb_out.empty() && m_usb_out.front().t_usb_ps <= now) {
        // The byte being shifted out has left the FIFO, so a full FIFO holds tx_fifo_bytes waiting bytes.
        if (m_tx_fifo.size() < m_cfg.tx_fifo_bytes) {
            m_tx_fifo.push_back(m_usb_out.front());
            arrived = true;
        } else {
            ++m_stats.tx_overflow_bytes;
        }
        m_usb_out.pop_front();
    }
    if (!m_usb_out.empty()) m_usb_out_ev.notify(ps(m_usb_out.front().t_usb_ps - now));
    if (arrived) m_tx_fifo_ev.notify(sc_core::SC_ZERO_TIME);
}

void Cp2102::tx_thread() {
    const int bits = m_cfg.format.bits_per_frame();
    for (;;) {
        while (m_tx_fifo.empty()) wait(m_tx_fifo_ev);
        // A burst of back-to-back frames is timed from its first start bit, frame j at bit boundary j * bits,
        // so that rounding to the picosecond never accumulates. The first start bit goes out at the instant
        // the byte reaches the FIFO (the chip's internal latency, a few 48 MHz core cycles, is not modelled).
        const TimePs t_burst = now_ps();
        m_tx_sending = true;
        for (std::int64_t j = 0; !m_tx_fifo.empty(); ++j) {
            const UsbOutByte b = m_tx_fifo.front();
            m_tx_fifo.pop_front();
            const TimePs t_start = t_burst + m_clk.bit_edge(j * bits);
            const TimePs t_end = t_burst + m_clk.bit_edge((j + 1) * bits);
            const auto sent = static_cast<std::size_t>(m_stats.tx_bytes++);
            m_stats.tx_line_busy_ps += t_end - t_start;
            if (sent >= m_tx_log_first && (sent - m_tx_log_first) % m_tx_log_stride == 0) {
                m_tx_log.push_back({b.byte, b.t_write_ps, b.t_usb_ps, t_start, t_end});
            }
            for (const Edge& e : frame_edges(b.byte, t_start, m_clk, m_cfg.format)) {
                m_txd_next_ps = e.t_ps;
                wait_until(e.t_ps);
                txd.write(e.level);
                m_txd_written_ps = e.t_ps;
            }
            m_txd_next_ps = t_end;  // the next byte's start bit, if one comes in time
            wait_until(t_end);
        }
        m_tx_sending = false;
    }
}

TimePs Cp2102::txd_quiet_until() const {
    const TimePs now = now_ps();
    if (now == m_txd_written_ps) return now;
    if (m_tx_sending) return std::max(now, m_txd_next_ps);
    if (!m_tx_fifo.empty()) return now;  // arrived this instant: the start bit goes out now
    return next_frame_start(now, m_cfg.usb_frame_ps);
}

void Cp2102::on_rxd() {
    const TimePs now = now_ps();
    const bool level = rxd.read();
    if (m_rx_busy) {
        m_rx_line.add(now, level);
        return;
    }
    if (level) return;  // a rise while idle (line released after a break or a framing error)
    m_rx_busy = true;
    m_rx_fall_ps = now;
    m_rx_line = EdgeLog{"rxd", true, {{now, false}}};
    m_rx_decide_ev.notify(ps(decision_offset_ps(m_clk, m_cfg.format)));
}

void Cp2102::log_rx(const RxByte& b) {
    m_stats.rx_line_busy_ps += b.t_stop_end_ps - b.t_start_bit_ps;
    m_rx_log.push_back(b);
}

void Cp2102::rx_decide() {
    const TimePs now = now_ps();
    m_rx_busy = false;
    const RxFrame f = receive_frame(m_rx_line, m_rx_fall_ps, m_clk, m_cfg.format);
    switch (f.status) {
        case RxStatus::FalseStart:
            ++m_stats.false_starts;
            return;
        case RxStatus::FramingError:
        case RxStatus::ParityError:
            // The CP2102 flags the error in its line status and discards the character: it never reaches
            // the host's read buffer (the VCP driver's default error handling).
            ++m_stats.framing_errors;
            log_rx({f.byte, m_rx_fall_ps, f.t_stop_end_ps, -1, true});
            return;
        case RxStatus::Ok:
            break;
    }
    // Bytes whose USB frame has not come yet are still in the chip's RX FIFO.
    const auto first_in_chip =
        std::partition_point(m_usb_in.begin(), m_usb_in.end(), [now](const UsbInByte& b) { return b.t_usb_ps <= now; });
    const auto in_chip = static_cast<std::size_t>(std::distance(first_in_chip, m_usb_in.end()));
    if (in_chip >= m_cfg.rx_fifo_bytes) {
        ++m_stats.rx_overflow_bytes;
        log_rx({f.byte, m_rx_fall_ps, f.t_stop_end_ps, -1, false});
        return;
    }
    const TimePs t_usb = next_frame_start(f.t_stop_end_ps, m_cfg.usb_frame_ps);
    const TimePs t_visible =
        spiked(m_in, t_usb, t_usb + m_cfg.usb_latency_ps, m_stats.usb_spikes_in, m_stats.usb_spike_delay_in_ps);
    m_usb_in.push_back({f.byte, t_usb, t_visible});
    log_rx({f.byte, m_rx_fall_ps, f.t_stop_end_ps, t_visible, false});
    m_rx_deliver_ev.notify(ps(t_visible - now));  // an earlier pending notification is kept
}

void Cp2102::rx_deliver() {
    const TimePs now = now_ps();
    bool delivered = false;
    while (!m_usb_in.empty() && m_usb_in.front().t_visible_ps <= now) {
        m_host_rx.push_back(m_usb_in.front().byte);
        m_usb_in.pop_front();
        delivered = true;
    }
    if (!m_usb_in.empty()) m_rx_deliver_ev.notify(ps(m_usb_in.front().t_visible_ps - now));
    if (delivered) m_data_ev.notify(sc_core::SC_ZERO_TIME);
}

std::optional<std::uint8_t> Cp2102::read_byte() {
    if (m_host_rx.empty()) return std::nullopt;
    const std::uint8_t b = m_host_rx.front();
    m_host_rx.pop_front();
    return b;
}

}  // namespace cnc::uart
